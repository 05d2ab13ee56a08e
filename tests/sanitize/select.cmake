# Turns tests/sanitize/tests.txt into a ctest -I argument: the numbers of the tests the sanitizer
# stage runs, written to OUT. Run by ./dev test --sanitize after the build:
#   ctest --show-only=json-v1 > tests.json
#   cmake -DLIST=tests.txt -DJSON=tests.json -DOUT=selected.txt -P select.cmake
# A line "TARGET [REGEX]" selects every test whose command runs TARGET's file (as the program or
# as an argument of a script) and whose ctest name matches ^(REGEX)$ (every name when omitted).
# A line that selects nothing is an error: a renamed test must not drop out of the stage quietly.
cmake_minimum_required(VERSION 3.25)

file(STRINGS "${LIST}" lines)
file(READ "${JSON}" json)
string(JSON count LENGTH "${json}" tests)
math(EXPR last "${count} - 1")

# The lines first (TARGET and REGEX each; names we write, safe as list elements).
set(targets)
foreach(line IN LISTS lines)
  string(REGEX REPLACE "#.*" "" line "${line}")
  string(STRIP "${line}" line)
  if(line STREQUAL "")
    continue()
  endif()
  # (Not REGEX REPLACE with "^": CMake applies it again at every match's end.)
  string(REGEX MATCH "^([^ \t]+)[ \t]*(.*)$" unused "${line}")
  list(LENGTH targets k)
  set(target_${k} "${CMAKE_MATCH_1}")
  set(regex_${k} "${CMAKE_MATCH_2}")
  if(regex_${k} STREQUAL "")
    set(regex_${k} ".*")
  endif()
  set(text_${k} "${line}")
  set(hits_${k} 0)
  list(APPEND targets "${k}")
endforeach()

# Then each test once: its name and the file names its command runs, matched against every
# line. (No list of names: a test name or argument holding '[' or ';' would split a CMake list.)
set(selected)
foreach(i RANGE ${last})
  string(JSON test GET "${json}" tests ${i})
  string(JSON name GET "${test}" name)
  string(JSON ncmd ERROR_VARIABLE no_cmd LENGTH "${test}" command)
  set(files "")
  if(NOT no_cmd AND ncmd GREATER 0)
    math(EXPR clast "${ncmd} - 1")
    foreach(c RANGE ${clast})
      string(JSON arg GET "${test}" command ${c})
      get_filename_component(arg "${arg}" NAME)
      string(APPEND files "<${arg}>")
    endforeach()
  endif()
  foreach(k IN LISTS targets)
    string(FIND "${files}" "<${target_${k}}>" at)
    if(at GREATER -1 AND name MATCHES "^(${regex_${k}})$")
      math(EXPR number "${i} + 1")
      list(APPEND selected ${number})
      math(EXPR hits_${k} "${hits_${k}} + 1")
    endif()
  endforeach()
endforeach()

set(bad "")
foreach(k IN LISTS targets)
  if(hits_${k} EQUAL 0)
    string(APPEND bad "  ${text_${k}}\n")
  endif()
endforeach()
if(NOT bad STREQUAL "")
  message(FATAL_ERROR "tests/sanitize/tests.txt: these lines select no test:\n${bad}")
endif()
list(REMOVE_DUPLICATES selected)
list(SORT selected COMPARE NATURAL)
list(LENGTH selected n)
list(JOIN selected "," numbers)
# ctest -I syntax: Start,End,Stride,test#,test#,... (an empty range, then the numbers). Given on
# the command line: ctest 3.25 runs every test when a file this long is given to -I instead.
file(WRITE "${OUT}" "0,0,0,${numbers}")
message(STATUS "sanitizer stage: ${n} of ${count} tests selected")

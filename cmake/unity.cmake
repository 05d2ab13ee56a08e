# Unity builds (CMakeLists.txt and fuzz/CMakeLists.txt): a source that compiles a single-header
# library's implementation (#define STB_..._IMPLEMENTATION, TINYGLTF_IMPLEMENTATION) stands
# alone, since in a unity batch its header may already have been included without it.
# ds_implementations_stand_alone(DIR) marks such sources of every target under DIR.
function(ds_implementations_stand_alone dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "UTILITY" OR type STREQUAL "INTERFACE_LIBRARY")
      continue()
    endif()
    get_target_property(sources ${target} SOURCES)
    get_target_property(source_dir ${target} SOURCE_DIR)
    foreach(src IN LISTS sources)
      cmake_path(ABSOLUTE_PATH src BASE_DIRECTORY ${source_dir})
      if(src MATCHES "\\.cpp$" AND EXISTS ${src})
        file(STRINGS ${src} defines REGEX "^#define [A-Z_]+_IMPLEMENTATION")
        if(defines)
          set_source_files_properties(${src} TARGET_DIRECTORY ${target}
            PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
        endif()
      endif()
    endforeach()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    ds_implementations_stand_alone(${sub})
  endforeach()
endfunction()

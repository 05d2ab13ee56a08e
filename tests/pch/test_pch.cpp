// The object that carries tests/pch/test_pch.h's precompiled header (tests/CMakeLists.txt).

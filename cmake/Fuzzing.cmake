# BPMKIT_ENABLE_LIBFUZZER: coverage-guided fuzzing of the input readers with clang's libFuzzer
# (tests/fuzz/). Every target is then compiled with coverage instrumentation and ASan/UBSan.
# scripts/test.sh (CI) builds them with clang and runs each for a fixed number of inputs (CTest
# label `fuzz`); the GCC builds run the seeded mutation loop of tests/io/reader_fuzz_test.cpp.
option(BPMKIT_ENABLE_LIBFUZZER "Build the libFuzzer targets of the scenario and CSV readers (clang only)" OFF)
if(BPMKIT_ENABLE_LIBFUZZER)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "BPMKIT_ENABLE_LIBFUZZER needs clang: configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

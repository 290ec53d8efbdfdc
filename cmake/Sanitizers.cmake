# ASan + UBSan for the whole build when BPMKIT_SANITIZE is on (CI runs the test suite this way).
if(BPMKIT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
  # GCC's flow analysis reports -Wmaybe-uninitialized false positives inside libstdc++ (<regex>,
  # std::function) once the sanitizers instrument the code; the GCC manual warns that these
  # sanitizer builds make the warning unreliable. The Release build keeps it as an error.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
endif()

# Tune for the building machine (AVX2/FMA where present): bpmkit is built where it runs, and the
# bond kernel is ~25 % faster with it. Turn BPMKIT_NATIVE off for portable binaries (packaging).
if(BPMKIT_NATIVE)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=native BPMKIT_HAS_MARCH_NATIVE)
  if(BPMKIT_HAS_MARCH_NATIVE)
    add_compile_options(-march=native)
  endif()
endif()

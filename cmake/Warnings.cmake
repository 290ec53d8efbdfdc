# Strict warnings for bpmkit's own targets; errors in CI (BPMKIT_WARNINGS_AS_ERRORS=ON).
function(bpmkit_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC 12 flags Eigen's AVX-512 reductions on -march=native machines that have AVX-512: the
    # intrinsic _mm256_undefined_pd() is "__m256d __Y = __Y;" by design (a false positive).
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
  if(BPMKIT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

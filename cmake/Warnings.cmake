# Strict warnings for bpmkit's own targets; errors in CI (BPMKIT_WARNINGS_AS_ERRORS=ON).
function(bpmkit_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    # GCC 12 flags Eigen's AVX-512 code on -march=native machines that have AVX-512 (as
    # -Wmaybe-uninitialized at -O3, as -Wuninitialized in the sanitizer build): the intrinsics
    # _mm256_undefined_pd() and _mm512_undefined_pd() are "__m512d __Y = __Y;" by design. A false
    # positive, GCC bug 105593, fixed in GCC 13.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized -Wno-uninitialized)
  endif()
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    # `omp simd` (the bond kernel's blocks) asks for vectorisation; Clang warns where it cannot
    # give it, as in the sanitizer-instrumented fuzz build. GCC, which builds bpmkit, vectorises
    # those loops (checked with -fopt-info-vec); a scalar loop is correct, only slower.
    target_compile_options(${target} PRIVATE -Wno-pass-failed)
  endif()
  if(BPMKIT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

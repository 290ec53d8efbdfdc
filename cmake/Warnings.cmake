# Strict warnings for bpmkit's own targets; errors in CI (BPMKIT_WARNINGS_AS_ERRORS=ON).
function(bpmkit_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
  if(BPMKIT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

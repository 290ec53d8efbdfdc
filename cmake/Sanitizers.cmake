# ASan + UBSan for the whole build when BPMKIT_SANITIZE is on (CI runs the test suite this way).
if(BPMKIT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# Warning and sanitizer flags applied to the project's own targets only
# (third-party headers are included as SYSTEM so their warnings stay out).
add_library(isosid_options INTERFACE)
target_compile_options(isosid_options INTERFACE -Wall -Wextra -Wpedantic)
if(ISOSID_SANITIZE)
  target_compile_options(isosid_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(isosid_options INTERFACE -fsanitize=address,undefined)
endif()

# Compiler warnings and sanitizers applied to every stella target through stella_options.
add_library(stella_options INTERFACE)
target_compile_options(stella_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow
                       -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Wunused
                       -Woverloaded-virtual -Wimplicit-fallthrough)
if(STELLA_WERROR)
  target_compile_options(stella_options INTERFACE -Werror)
endif()
if(STELLA_SANITIZE)
  target_compile_options(stella_options INTERFACE -fsanitize=address,undefined
                         -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(stella_options INTERFACE -fsanitize=address,undefined)
endif()

# rotorcert_warnings(target): the project's warning set, for gcc 12 and clang 14 alike.
function(rotorcert_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(ROTORCERT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

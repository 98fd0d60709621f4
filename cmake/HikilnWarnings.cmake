# Strict warnings for project code only (never for dependencies). CI turns them into errors.
add_library(hikiln_warnings INTERFACE)
target_compile_options(hikiln_warnings INTERFACE
  $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough>
  $<$<AND:$<BOOL:${HIKILN_WARNINGS_AS_ERRORS}>,$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>>:-Werror>)

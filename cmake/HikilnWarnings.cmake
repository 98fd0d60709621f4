# Strict warnings for project code only (never for dependencies). CI turns them into errors.
add_library(hikiln_warnings INTERFACE)
target_compile_options(hikiln_warnings INTERFACE
  $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough>
  $<$<AND:$<BOOL:${HIKILN_WARNINGS_AS_ERRORS}>,$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>>:-Werror>)

# Through nvcc_wrapper the flags above reach only the host compiler; nvcc's own front end warns
# separately, e.g. #20011 "calling a __host__ function from a __host__ __device__ function", which
# is a real bug in a kernel. Promote those to errors too. (Only when the C++ compiler itself is
# nvcc: with Kokkos' launcher some targets compile with plain g++, which rejects -Xcudafe.)
if(HIKILN_WARNINGS_AS_ERRORS)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} --version OUTPUT_VARIABLE _hikiln_cxx_version
                  ERROR_QUIET)
  if(_hikiln_cxx_version MATCHES "nvcc")
    target_compile_options(hikiln_warnings INTERFACE
      "$<$<COMPILE_LANGUAGE:CXX>:SHELL:-Xcudafe --promote_warnings>")
  endif()
endif()

#include "drivers/app/Commands.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::app {

std::vector<std::string> enabledBackends() {
  std::vector<std::string> names;
#ifdef KOKKOS_ENABLE_SERIAL
  names.emplace_back("Serial");
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  names.emplace_back("OpenMP");
#endif
#ifdef KOKKOS_ENABLE_CUDA
  names.emplace_back("Cuda");
#endif
  return names;
}

std::string defaultBackend() {
  return Kokkos::DefaultExecutionSpace::name();
}

} // namespace hikiln::app

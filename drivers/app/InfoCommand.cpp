// `hikiln info`: what this build can run on. Useful first thing in a bug report.
#include "drivers/app/Commands.hpp"
#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <sstream>

#ifdef KOKKOS_ENABLE_CUDA
#include <cuda_runtime_api.h>
#endif

namespace hikiln::app {

namespace {

nlohmann::json collectInfo() {
  nlohmann::json info;
  info["hikiln_version"] = HIKILN_VERSION;
  info["kokkos_version"] = kokkosVersionString();
  info["backends"] = enabledBackends();
  info["default_backend"] = defaultBackend();
  info["default_concurrency"] = Kokkos::DefaultExecutionSpace::concurrency();
  info["host_concurrency"] = Kokkos::DefaultHostExecutionSpace::concurrency();
  nlohmann::json gpus = nlohmann::json::array();
#ifdef KOKKOS_ENABLE_CUDA
  int count = 0;
  if (cudaGetDeviceCount(&count) == cudaSuccess) {
    for (int d = 0; d < count; ++d) {
      cudaDeviceProp prop{};
      if (cudaGetDeviceProperties(&prop, d) != cudaSuccess)
        continue;
      gpus.push_back({{"name", prop.name},
                      {"memory_gib", static_cast<double>(prop.totalGlobalMem) / (1 << 30)},
                      {"compute_capability", fmt::format("{}.{}", prop.major, prop.minor)}});
    }
  }
#endif
  info["gpus"] = gpus;
  return info;
}

} // namespace

void addInfoCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("info", "Print versions, enabled backends, threads and GPUs");
  auto json = std::make_shared<bool>(false);
  auto detail = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print as JSON");
  cmd->add_flag("--kokkos-config", *detail, "Also print Kokkos' full build configuration");
  cmd->callback([&action, json, detail] {
    action = [json, detail] {
      const auto info = collectInfo();
      if (*json) {
        std::cout << info.dump(2) << "\n";
      } else {
        std::cout << fmt::format("hikiln {}\n", info["hikiln_version"].get<std::string>())
                  << fmt::format("Kokkos {}\n", info["kokkos_version"].get<std::string>());
        std::string backends;
        for (const auto& b : info["backends"])
          backends += (backends.empty() ? "" : ", ") + b.get<std::string>();
        std::cout << "backends: " << backends << " (default "
                  << info["default_backend"].get<std::string>() << ", "
                  << info["default_concurrency"] << " threads/lanes; host "
                  << info["host_concurrency"] << " threads)\n";
        if (info["gpus"].empty())
          std::cout << "GPUs: none\n";
        for (const auto& g : info["gpus"]) {
          std::cout << fmt::format("GPU: {} ({:.1f} GiB, sm {})\n", g["name"].get<std::string>(),
                                   g["memory_gib"].get<double>(),
                                   g["compute_capability"].get<std::string>());
        }
      }
      if (*detail) {
        std::ostringstream config;
        Kokkos::print_configuration(config, true);
        std::cout << config.str();
      }
      return 0;
    };
  });
}

} // namespace hikiln::app

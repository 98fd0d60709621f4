#pragma once
/// \file InitialTemperature.hpp
/// \brief Initial temperature fields for DemHeat: a function of a particle's position and id,
/// evaluated once per particle on the host (all shells and layers of the particle start at it).

#include <cstdint>
#include <functional>
#include <utility>

namespace hikiln::dem {

/// \brief Temperature (K) of the particle with centre (x, y) and id.
using TemperatureField = std::function<double(double x, double y, std::int64_t id)>;

/// \brief The same temperature everywhere.
inline TemperatureField uniformTemperature(double t) {
  return [t](double, double, std::int64_t) { return t; };
}

/// \brief `left` for centres with x < xSplit, `right` otherwise (physics.md 6.2: the left and the
/// right half of the bed, split at the drum axis).
inline TemperatureField leftRightTemperature(double xSplit, double left, double right) {
  return [=](double x, double, std::int64_t) { return x < xSplit ? left : right; };
}

/// \brief `inside` for centres where region(x, y) holds, `outside` elsewhere.
inline TemperatureField regionTemperature(std::function<bool(double, double)> region, double inside,
                                          double outside) {
  return [region = std::move(region), inside, outside](double x, double y, std::int64_t) {
    return region(x, y) ? inside : outside;
  };
}

} // namespace hikiln::dem

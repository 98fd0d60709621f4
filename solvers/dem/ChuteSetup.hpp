#pragma once
/// \file ChuteSetup.hpp
/// \brief A 2D periodic chute on a rough base (verification of the DEM engine against Bagnold's
/// profile), and its slab-averaged depth profiles.
///
/// Geometry: x runs down the slope, periodic over `length`; y is normal to the bed. The base is a
/// row of fixed discs (ParticleKind::Fixed) with centres near y = 0, one per mean diameter, their
/// sizes and heights drawn at random so that the flow cannot lock into the base's period. The
/// free discs start at rest on a loose lattice above it; gravity is tilted by the slope angle,
/// g = g (sin theta, -cos theta).
///
/// Profiles: slabs of constant y above the base; a disc contributes the exact area of its part
/// inside each slab (circle-strip intersection), so the solid fraction is area / slab area and the
/// velocity is the area-weighted mean of vx (all discs have the same density).

#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <cstdint>
#include <vector>

namespace hikiln::dem {

/// \brief What a chute is made of (SI units; lengths given in mean diameters where named so).
struct ChuteSpec {
  double meanDiameter = 0.02;    ///< m
  double sizeRange = 0.2;        ///< free discs uniform in mean * (1 +- range): no crystallisation
  double baseSizeRange = 0.2;    ///< base discs likewise
  double baseHeightJitter = 0.2; ///< base disc centres at y uniform in +- jitter mean diameters
  double density = 2700.0;       ///< kg/m^3 (sphere mass convention, as the drum)
  double lengthDiameters = 20.0; ///< periodic length (mean diameters)
  double heightDiameters = 20.0; ///< bed thickness aimed at (mean diameters, at solid fraction 0.8)
  double angleDegrees = 22.0;    ///< slope
  double gravity = 9.81;         ///< m/s^2
  std::uint64_t seed = 1;
  ContactParameters contact; ///< the law between all discs (defaults: physics.md base case)
};

/// \brief A chute ready to run: the configuration (periodic in x, tilted gravity, no walls) and the
/// particles (base first, ids 0.., then the free discs).
struct Chute {
  DemConfig config;
  ParticleArrays<Kokkos::HostSpace> particles;
  double length = 0.0;  ///< periodic length (m)
  double baseTop = 0.0; ///< mean top of the base discs (m): z = y - baseTop is the depth axis
  std::size_t baseCount = 0;
};

/// \brief Builds a chute from a specification; throws std::invalid_argument on impossible ones.
Chute makeChute(const ChuteSpec& spec);

/// \brief Time-averaged depth profiles of a chute.
struct ChuteProfile {
  std::vector<double> z;             ///< slab centres above the base top (m)
  std::vector<double> solidFraction; ///< per slab
  std::vector<double> velocity;      ///< area-weighted mean vx per slab (m/s), NaN when empty
  double slab = 0.0;                 ///< slab thickness (m)
  double height = 0.0; ///< flow height: where the solid fraction falls below half the bulk's (m)
  double bulkSolidFraction = 0.0; ///< mean over the slabs between 0.25 and 0.75 of the height
};

/// \brief Accumulates slab sums of the free discs over samples.
class ChuteProfileSampler {
public:
  /// \brief Slabs of thickness `slab` from baseTop up to baseTop + top.
  ChuteProfileSampler(double length, double baseTop, double slab, double top);
  /// \brief Adds one sample (host copy of the particles; only free ones count).
  void add(const ParticleArrays<Kokkos::HostSpace>& particles);
  /// \brief Number of samples so far.
  int samples() const { return _samples; }
  /// \brief The averaged profiles of the samples so far.
  ChuteProfile profile() const;

private:
  double _length, _baseTop, _slab;
  std::vector<double> _area, _momentum;
  int _samples = 0;
};

/// \brief Least-squares fit of u(z) = u0 + A (h^a - (h - z)^a) for a given flow height h and
/// exponent a (Bagnold: a = 3/2) over the slabs with zMin <= z <= zMax.
struct ProfileFit {
  double u0 = 0.0, amplitude = 0.0, exponent = 0.0;
  double rSquared = 0.0; ///< 1 - SS_res / SS_tot
  int points = 0;
};

/// \brief Fit with a fixed exponent (see ProfileFit).
ProfileFit fitPowerProfile(const ChuteProfile& p, double exponent, double zMin, double zMax);

/// \brief The exponent in [0.5, 3] (steps of 0.01) whose fit has the smallest residual.
ProfileFit fitBestExponent(const ChuteProfile& p, double zMin, double zMax);

} // namespace hikiln::dem

#pragma once
/// \file DrumFill.hpp
/// \brief Filling a drum to a requested fill fraction (host side, run once before a DEM slice).
///
/// Fill is the bed area including voids over the drum area (physics.md 1). The recipe:
/// 1. generateDrumLattice(): discs on a hexagonal lattice in the lower part of the drum, overfilled
///    (a loose lattice packs less densely than a settled bed), radii from a seeded uniform law;
/// 2. the caller settles them under gravity;
/// 3. measureBed() finds the settled bulk solid fraction phi; trimToFill() removes the highest
///    particles until the solids area equals fill * phi * pi R^2;
/// 4. the caller settles again and measureBed() reports the fill reached.
///
/// A rough shell (shellBumpDiameter > 0) is a ring of discs glued to the shell
/// (ParticleKind::Shell, rotating with it) whose centres sit at R - d_b/2; the lattice then starts
/// inside R - d_b. Fill stays relative to the full drum area pi R^2 (the ring is not bed), so a
/// rough drum holds about as many free particles as a smooth one. measureBed() and trimToFill()
/// look at free particles only (trimming keeps the ring).
///
/// Blocky particles (FillSpec::shape superquadric, DrumShapes.hpp): the drawn diameters are
/// equal-area diameters, the lattice is spaced by the bounding diameter, each particle gets a
/// random orientation from the seed (drawn after all sizes, so a seed gives the same sizes for
/// every shape), and measureBed()/trimToFill() use the true particle areas.

#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "solvers/dem/DrumShapes.hpp"

#include <cstdint>

namespace hikiln::dem {

/// \brief Particle sizes and material of a drum fill.
struct FillSpec {
  double drumRadius = 1.0;           ///< m
  double fill = 0.2;                 ///< requested bed area fraction, (0, 1)
  double meanDiameter = 0.02;        ///< m
  double sizeRange = 0.05;           ///< diameters uniform in mean * [1 - range, 1 + range]
  double minDiameterFraction = 0.05; ///< floor on diameters (a +-100 % range would reach 0)
  double density = 2700.0;           ///< kg/m^3
  MassConvention convention = MassConvention::Sphere;
  double thickness = 0.02; ///< m, for MassConvention::Disc
  std::uint64_t seed = 12345;
  double overfill = 1.35;         ///< lattice area over the target bed area
  double shellBumpDiameter = 0.0; ///< m; 0: smooth shell, else the ring of glued discs
  double shellBumpSpacing = 1.0;  ///< ring centre distance over the bump diameter (>= 1)
  ParticleShapeSpec shape;        ///< discs, or superquadrics of meanDiameter's area
};

/// \brief Particles of a drum and, for blocky particles, their shapes and orientations (same
/// order; capacity 0 for discs).
struct DrumParticles {
  ParticleArrays<Kokkos::HostSpace> particles;
  BlockyArrays<Kokkos::HostSpace> shapes;
  /// \brief Whether the particles carry shapes (a blocky system).
  bool blocky() const { return shapes.capacity() > 0; }
};

/// \brief What measureBed() finds in a settled (or flowing) bed.
struct BedMeasurement {
  double solidArea = 0.0;     ///< sum of particle areas (m^2)
  double bulkFraction = 0.0;  ///< solid area fraction in the bed's interior
  double fill = 0.0;          ///< solidArea / (bulkFraction pi R^2)
  double surfaceHeight = 0.0; ///< mean top of the bed (m), from the highest particles per bin
  std::size_t count = 0;      ///< particles
};

/// \brief Area of the part of a circle of radius R below the horizontal line y = h.
double circularSegmentArea(double radius, double height);

/// \brief Height h at which circularSegmentArea(R, h) = fraction * pi R^2 (bisection).
double segmentHeightForFraction(double radius, double fraction);

/// \brief Discs on a hexagonal lattice filling the lower part of the drum (ids 0..n-1, at rest,
/// mass properties set), followed by the ring of shell discs when the spec asks for a rough shell
/// (ids n.., kind Shell). Throws std::invalid_argument for impossible specifications, and for a
/// blocky spec (generateDrumParticles() gives the shapes too).
ParticleArrays<Kokkos::HostSpace> generateDrumLattice(const FillSpec& spec);

/// \brief As generateDrumLattice(), for any particle shape: blocky particles get their shapes,
/// random orientations and mass properties (assignBlockyMassPropertiesHost(): radius = bounding
/// radius), the shell discs circle shapes.
DrumParticles generateDrumParticles(const FillSpec& spec);

/// \brief Measures the bed (free particles only): bulk solid fraction from the particles whose
/// centres lie at least two mean diameters inside the wall (or the shell discs' inner reach) and
/// below the surface, and the fill implied by it. With `shapes` (one per particle) areas are the
/// superquadrics' and the particle size in the surface and reach tests the equal-area radius.
BedMeasurement measureBed(const ParticleArrays<Kokkos::HostSpace>& particles, double drumRadius,
                          const BlockyArrays<Kokkos::HostSpace>& shapes = {});

/// \brief Copy of `particles` without the highest ones, so that the solid area is
/// fill * bulkFraction * pi R^2 (at most one disc area off); all of them if there are too few.
/// Ids are kept.
ParticleArrays<Kokkos::HostSpace> trimToFill(const ParticleArrays<Kokkos::HostSpace>& particles,
                                             double drumRadius, double fill, double bulkFraction);

/// \brief trimToFill() for particles of any shape: blocky ones by their true areas, the kept
/// particles' shapes and orientations kept with them.
DrumParticles trimToFill(const DrumParticles& particles, double drumRadius, double fill,
                         double bulkFraction);

} // namespace hikiln::dem

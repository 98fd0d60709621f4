#pragma once
/// \file DemState.hpp
/// \brief Host copy of everything a DEM run needs to continue bitwise identically (for
/// checkpoints).

#include <cstdint>
#include <vector>

namespace hikiln::dem {

/// \brief Exported DEM state: particles in their current order, the contact history keyed by ids,
/// and the clock. Vectors of 2D quantities are interleaved (x0, y0, x1, y1, ...); wallShear holds
/// wallSlotCount values per particle (slot 0 drum, 1 + k flat wall k).
struct DemState {
  std::int64_t step = 0;
  double time = 0.0;
  std::vector<std::int64_t> id;
  std::vector<double> position;
  std::vector<double> velocity;
  std::vector<double> angularVelocity;
  std::vector<double> force; ///< forces of the last evaluation (the next half kick needs them)
  std::vector<double> torque;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;
  std::vector<double> wallShear;
  /// ParticleKind per particle (empty: all free, as states written before kinds existed).
  std::vector<std::uint8_t> kind;
  double shellAngle = 0.0;       ///< rotation of the shell particles since their home positions
  std::vector<double> shellHome; ///< home positions of shell particles, in id order (x, y, ...)
  /// Pair history, one entry per (particle, neighbour) slot with a non-zero shear displacement;
  /// both directions of a pair are present.
  std::vector<std::int64_t> contactId;
  std::vector<std::int64_t> contactNeighborId;
  std::vector<double> contactShear;
  /// Blocky systems only (all empty for discs): orientation (rad) and shape (semi-axes a, b and
  /// blockiness N) per particle, and per contact entry the pair's stored search direction
  /// (NeighborList::normalAngle; entries exist where the shear or this is non-zero).
  std::vector<double> orientation;
  std::vector<double> shapeA;
  std::vector<double> shapeB;
  std::vector<double> shapeN;
  std::vector<double> contactAngle;
  /// Batches only (DemBatch.hpp; empty otherwise): the slice of each particle.
  std::vector<int> slice;

  /// \brief Number of particles.
  std::size_t size() const { return id.size(); }
};

} // namespace hikiln::dem

#pragma once
/// \file FieldOps.hpp
/// \brief Vector operations on the unknowns of a grid field (the box an AxisClosure triple
/// defines): dot products, sums, axpby, fill, and packing into a flat vector (dense coarse solve,
/// sparse-matrix baseline). Ghosts and boundary nodes are never touched.

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/SplitLoop.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>

namespace hikiln::cfd {

/// \brief The logical index box [lo, hi) of a field's unknowns and its storage offsets.
struct UnknownBox {
  int lo[3] = {0, 0, 0};
  int hi[3] = {0, 0, 0};
  GhostOffsets offsets;

  /// \brief Number of unknowns.
  KOKKOS_INLINE_FUNCTION std::int64_t size() const {
    return static_cast<std::int64_t>(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
  /// \brief Position of unknown (i, j, k) in a flat vector, i fastest.
  KOKKOS_INLINE_FUNCTION std::int64_t linear(int i, int j, int k) const {
    return (i - lo[0]) + static_cast<std::int64_t>(hi[0] - lo[0]) *
                             ((j - lo[1]) + static_cast<std::int64_t>(hi[1] - lo[1]) * (k - lo[2]));
  }
};

/// \brief The unknown box of a field with closures axes on grid.
inline UnknownBox unknownBox(Grid const& grid, AxisClosure const (&axes)[3]) {
  UnknownBox box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = axes[a].begin();
    box.hi[a] = axes[a].end();
  }
  box.offsets = ghostOffsets(grid);
  return box;
}

/// \brief Sum over the box of a * b.
template <class ExecutionSpace, class MemorySpace>
double dotUnknowns(ExecutionSpace const& space, UnknownBox const& box, Field<MemorySpace> const& a,
                   Field<MemorySpace> const& b) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::dotUnknowns: fields not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::dotUnknowns", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& s) {
        s += a(i + o.x, j + o.y, k + o.z) * b(i + o.x, j + o.y, k + o.z);
      },
      sum);
  return sum;
}

/// \brief Sum over the box of a.
template <class ExecutionSpace, class MemorySpace>
double sumUnknowns(ExecutionSpace const& space, UnknownBox const& box,
                   Field<MemorySpace> const& a) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::sumUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::sumUnknowns", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& s) {
        s += a(i + o.x, j + o.y, k + o.z);
      },
      sum);
  return sum;
}

/// \brief Largest |a| over the box.
template <class ExecutionSpace, class MemorySpace>
double maxAbsUnknowns(ExecutionSpace const& space, UnknownBox const& box,
                      Field<MemorySpace> const& a) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::maxAbsUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  double result = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::maxAbsUnknowns", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& m) {
        m = math::fmax(m, math::fabs(a(i + o.x, j + o.y, k + o.z)));
      },
      Kokkos::Max<double>(result));
  return result;
}

/// \brief y = alpha x + beta y over the box (beta = 0 ignores y's old values).
template <class ExecutionSpace, class MemorySpace>
void axpbyUnknowns(ExecutionSpace const& space, UnknownBox const& box, double alpha,
                   Field<MemorySpace> const& x, double beta, Field<MemorySpace> const& y) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::axpbyUnknowns: fields not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  if (beta == 0.0) { // y is not read (it may hold anything); two launches keep the rows branch-free
    forEachBoxCell(
        space, "hikiln::cfd::axpbyUnknowns", box.lo, box.hi,
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          // + 0.0 as the one-launch form added it: -0.0 stays +0.0, the same bits as before
          y(i + o.x, j + o.y, k + o.z) = alpha * x(i + o.x, j + o.y, k + o.z) + 0.0;
        });
    return;
  }
  forEachBoxCell(
      space, "hikiln::cfd::axpbyUnknowns", box.lo, box.hi,
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        double& target = y(i + o.x, j + o.y, k + o.z);
        target = alpha * x(i + o.x, j + o.y, k + o.z) + beta * target;
      });
}

/// \brief y = value on the box.
template <class ExecutionSpace, class MemorySpace>
void fillUnknowns(ExecutionSpace const& space, UnknownBox const& box, double value,
                  Field<MemorySpace> const& y) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::fillUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  forEachBoxCell(
      space, "hikiln::cfd::fillUnknowns", box.lo, box.hi,
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        y(i + o.x, j + o.y, k + o.z) = value;
      });
}

/// \brief y = 1 where x > 0, else 0, on the box.
template <class ExecutionSpace, class MemorySpace>
void indicatorUnknowns(ExecutionSpace const& space, UnknownBox const& box,
                       Field<MemorySpace> const& x, Field<MemorySpace> const& y) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::indicatorUnknowns: fields not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  forEachBoxCell(
      space, "hikiln::cfd::indicatorUnknowns", box.lo, box.hi,
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        y(i + o.x, j + o.y, k + o.z) = x(i + o.x, j + o.y, k + o.z) > 0.0 ? 1.0 : 0.0;
      });
}

/// \brief y += value on the box.
template <class ExecutionSpace, class MemorySpace>
void addToUnknowns(ExecutionSpace const& space, UnknownBox const& box, double value,
                   Field<MemorySpace> const& y) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::addToUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  forEachBoxCell(
      space, "hikiln::cfd::addToUnknowns", box.lo, box.hi,
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        y(i + o.x, j + o.y, k + o.z) += value;
      });
}

/// \brief Removes the mean over the box from y (the null space of a pure Neumann/periodic
/// operator); returns the mean that was removed.
template <class ExecutionSpace, class MemorySpace>
double removeMean(ExecutionSpace const& space, UnknownBox const& box, Field<MemorySpace> const& y) {
  const double mean = sumUnknowns(space, box, y) / static_cast<double>(box.size());
  addToUnknowns(space, box, -mean, y);
  return mean;
}

/// \brief vector(offset + box.linear(i, j, k)) = field(i, j, k) over the box.
template <class ExecutionSpace, class MemorySpace, class VectorView>
void packUnknowns(ExecutionSpace const& space, UnknownBox const& box,
                  Field<MemorySpace> const& field, VectorView const& vector, std::int64_t offset) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::packUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  Kokkos::parallel_for(
      "hikiln::cfd::packUnknowns", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        vector(offset + box.linear(i, j, k)) = field(i + o.x, j + o.y, k + o.z);
      });
}

/// \brief field(i, j, k) = vector(offset + box.linear(i, j, k)) over the box.
template <class ExecutionSpace, class MemorySpace, class VectorView>
void unpackUnknowns(ExecutionSpace const& space, UnknownBox const& box, VectorView const& vector,
                    std::int64_t offset, Field<MemorySpace> const& field) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::unpackUnknowns: field not accessible from the execution space");
  const GhostOffsets o = box.offsets;
  Kokkos::parallel_for(
      "hikiln::cfd::unpackUnknowns", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        field(i + o.x, j + o.y, k + o.z) = vector(offset + box.linear(i, j, k));
      });
}

} // namespace hikiln::cfd

#pragma once
/// \file GhostFill.hpp
/// \brief Ghost layers (and boundary nodes of the normal velocity) from the boundary conditions.
/// The solvers do not need ghosts (they use AxisClosure); explicit stencils that read a field's
/// neighbours directly (gradients, divergence, advection) call these first.
///
/// Rules per side, ghost layer m = 0, 1, ... outward:
/// - periodic: the opposite interior continues (node n is node 0);
/// - even (Wall for a scalar): mirror image of the interior, zero normal gradient;
/// - odd about a value v (scalar Value, tangential velocity at a Wall/Value side): 2 v - mirror,
///   so the boundary face carries v;
/// - node-centred with a value (normal velocity): the boundary node is set to v and the ghosts
///   are 2 v - mirror about it.
/// Axes are filled x, then y, then z, each over the full extent of the others, so edges and
/// corners are consistent.

#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

/// \brief The ghost rule of one side (see the file comment).
enum class GhostRule : int { Periodic = 0, Even = 1, Odd = 2 };

/// \brief Fills the ghost layers of `field` (staggering s) along one axis with the rules and
/// values of its low and high side.
template <class ExecutionSpace, class MemorySpace>
void fillGhostsAlong(ExecutionSpace const& space, Grid const& grid, Staggering s, int axis,
                     GhostRule lowRule, double lowValue, GhostRule highRule, double highValue,
                     Field<MemorySpace> const& field) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::fillGhostsAlong: field not accessible from the execution space");
  const int g = grid.ghostAlong(axis);
  const int n = grid.cells(axis);
  const bool node = isNodeCentred(s, axis);
  const int b = (axis + 1) % 3;
  const int c = (axis + 2) % 3;
  const int off[3] = {grid.ghostAlong(0), grid.ghostAlong(1), grid.ghostAlong(2)};
  const int loB = -off[b], hiB = grid.cells(b) + (isNodeCentred(s, b) ? 1 : 0) + off[b];
  const int loC = -off[c], hiC = grid.cells(c) + (isNodeCentred(s, c) ? 1 : 0) + off[c];
  if (node) {
    // boundary nodes first: they are the data the ghost mirrors below reflect about
    Kokkos::parallel_for(
        "hikiln::cfd::fillBoundaryNodes", gridPolicy(space, {0, loB, loC}, {1, hiB, hiC}),
        KOKKOS_LAMBDA(const int, const int p, const int q) {
          int lowIdx[3], highIdx[3];
          lowIdx[b] = highIdx[b] = p + off[b];
          lowIdx[c] = highIdx[c] = q + off[c];
          lowIdx[axis] = off[axis];
          highIdx[axis] = n + off[axis];
          double& lowNode = field(lowIdx[0], lowIdx[1], lowIdx[2]);
          double& highNode = field(highIdx[0], highIdx[1], highIdx[2]);
          if (lowRule == GhostRule::Periodic) {
            highNode = lowNode;
          } else {
            if (lowRule == GhostRule::Odd) {
              lowNode = lowValue;
            }
            if (highRule == GhostRule::Odd) {
              highNode = highValue;
            }
          }
        });
  }
  if (g == 0) {
    return;
  }
  Kokkos::parallel_for(
      "hikiln::cfd::fillGhosts", gridPolicy(space, {0, loB, loC}, {g, hiB, hiC}),
      KOKKOS_LAMBDA(const int m, const int p, const int q) {
        int idx[3];
        idx[b] = p + off[b];
        idx[c] = q + off[c];
        auto at = [&](int logical) -> double& {
          idx[axis] = logical + off[axis];
          return field(idx[0], idx[1], idx[2]);
        };
        // mirror partners: cells reflect about the boundary face, nodes about the boundary node
        const int lowGhost = -1 - m;
        const int highGhost = node ? n + 1 + m : n + m;
        const int lowMirror = node ? 1 + m : m;
        const int highMirror = n - 1 - m;
        const int lowPeriodic = n - 1 - m;
        const int highPeriodic = node ? 1 + m : m;
        double value;
        if (lowRule == GhostRule::Periodic) {
          value = at(lowPeriodic);
        } else {
          value = at(lowMirror);
          value = lowRule == GhostRule::Odd ? 2.0 * lowValue - value : value;
        }
        at(lowGhost) = value;
        if (highRule == GhostRule::Periodic) {
          value = at(highPeriodic);
        } else {
          value = at(highMirror);
          value = highRule == GhostRule::Odd ? 2.0 * highValue - value : value;
        }
        at(highGhost) = value;
      });
}

/// \brief Fills every ghost layer of a cell-centred scalar from its boundary conditions.
template <class ExecutionSpace, class MemorySpace>
void fillGhostsScalar(ExecutionSpace const& space, Grid const& grid, ScalarBoundaries const& bc,
                      Field<MemorySpace> const& field) {
  const auto rule = [](BoundaryKind k) {
    return k == BoundaryKind::Periodic
               ? GhostRule::Periodic
               : (k == BoundaryKind::Value ? GhostRule::Odd : GhostRule::Even);
  };
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    fillGhostsAlong(space, grid, Staggering::Cell, a, rule(bc.kind[2 * a]), bc.value[2 * a],
                    rule(bc.kind[2 * a + 1]), bc.value[2 * a + 1], field);
  }
}

/// \brief Fills the boundary nodes and ghost layers of MAC velocity component `component` (u on
/// x-faces, v, w) from the velocity boundary conditions.
template <class ExecutionSpace, class MemorySpace>
void fillGhostsVelocity(ExecutionSpace const& space, Grid const& grid, VelocityBoundaries const& bc,
                        int component, Field<MemorySpace> const& field) {
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    // Inflow and Outflow keep the normal component's boundary nodes (data) and mirror the
    // ghosts; an Outflow's tangential components have zero gradient
    const auto rule = [&](BoundaryKind k) {
      if (k == BoundaryKind::Periodic) {
        return GhostRule::Periodic;
      }
      const bool open = k == BoundaryKind::Inflow || k == BoundaryKind::Outflow;
      return (open && a == component) || k == BoundaryKind::Outflow ? GhostRule::Even
                                                                    : GhostRule::Odd;
    };
    fillGhostsAlong(space, grid, faceStaggering(component), a, rule(bc.kind[2 * a]),
                    bc.velocity[2 * a][component], rule(bc.kind[2 * a + 1]),
                    bc.velocity[2 * a + 1][component], field);
  }
}

} // namespace hikiln::cfd

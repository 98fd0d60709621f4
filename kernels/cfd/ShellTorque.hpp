#pragma once
/// \file ShellTorque.hpp
/// \brief The torque budget of a 2D drum about its axis, per metre of drum: what turns the bed
/// (the shell's drag on the cut faces) against what holds it back (gravity), and the pressure's
/// share. On a real circular wall the pressure is normal and has no torque. Every open face
/// counts with the volume hx hy its momentum equation gives it and its arm at the centroid of its
/// open part, as the wall velocity is taken there. Gravity and pressure on a cut face count with
/// the weight the predictor gives them: the aperture with the incremental projection
/// (CarriedAcceleration.hpp; the pressure's torque then vanishes), 1 with the plain one, whose
/// projection applies them to the whole face. The drag is (alpha - rho_face / dt)(u_wall - u*) with
/// the alpha and the predicted velocity u* of the last momentum predictor (TwoPhaseSolver keeps
/// it); its bound is the Coulomb cap per cut face, WallFriction::capForce (ProjectionKernels.hpp).
/// The drag on the gas the shell holds (WallFriction::gasShare) is counted but not bounded; in a
/// drum it is small (the gas is light and turns with the shell).
/// At a steady state gravity + pressure + drag is about 0 (the viscous stresses add no torque but
/// through the cut faces' Brinkman terms, which the drag includes).

#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ProjectionKernels.hpp"
#include "kernels/cfd/ShellGeometry.hpp"

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace hikiln::cfd {

/// \brief True for shapes with an axis (cx, cy): the drum and kiln shells.
template <class Shape, class = void> struct HasAxis : std::false_type {};
template <class Shape>
struct HasAxis<Shape, std::void_t<decltype(Shape::cx), decltype(Shape::cy)>> : std::true_type {};

/// \brief Torques about the axis [N m per metre of drum], counter-clockwise positive.
struct ShellTorque {
  double gravity = 0.0;       ///< rho_face g on the open faces
  double pressure = 0.0;      ///< -grad p on the open faces
  double pressureCut = 0.0;   ///< the part of `pressure` on the cut faces
  double wallDrag = 0.0;      ///< the shell's drag on the cut faces
  double wallDragBound = 0.0; ///< sum over the cut faces of mu_wall sigma h |arm|

  ShellTorque& operator+=(ShellTorque const& o) {
    gravity += o.gravity;
    pressure += o.pressure;
    pressureCut += o.pressureCut;
    wallDrag += o.wallDrag;
    wallDragBound += o.wallDragBound;
    return *this;
  }
};

/// \brief The budget of one face component c of a 2D grid (see the file comment).
template <class ExecutionSpace, class MemorySpace, class Shape>
ShellTorque shellTorqueOfComponent(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                                   Shape const& shape, int c, Field<MemorySpace> const& u,
                                   Field<MemorySpace> const& rhoFace,
                                   Field<MemorySpace> const& alpha, Field<MemorySpace> const& p,
                                   Field<MemorySpace> const& pBed, double gravity, double dt,
                                   WallFriction const& friction, bool openShareOnCutFaces) {
  const Grid grid = cc.grid;
  const int g = grid.ghost;
  const auto ap = cc.aperture[c];
  const auto cx = cc.centroid[c][0], cy = cc.centroid[c][1];
  const int last = grid.cells(c);
  const bool periodic = cc.periodic[c];
  const double volume = grid.hx * grid.hy;
  const double h = grid.spacing(c); // across the face, for grad p
  const double axisX = shape.cx, axisY = shape.cy;
  ShellTorque t;
  Kokkos::parallel_reduce(
      "hikiln::cfd::shellTorque",
      Kokkos::MDRangePolicy<ExecutionSpace, Kokkos::Rank<2>>(
          space, {0, 0}, {grid.nx + (c == 0 ? 1 : 0), grid.ny + (c == 1 ? 1 : 0)}),
      KOKKOS_LAMBDA(const int i, const int j, double& gravitySum, double& pressureSum,
                    double& pressureCutSum, double& dragSum, double& boundSum) {
        const int n = c == 0 ? i : j;
        const int I = i + g, J = j + g;
        const double open = ap(I, J, 0);
        if ((!periodic && (n == 0 || n == last)) || !(open > 0.0)) {
          return;
        }
        const int Il = c == 0 ? I - 1 : I, Jl = c == 1 ? J - 1 : J;
        const double x = cx(I, J, 0), y = cy(I, J, 0);
        const double arm = c == 0 ? -(y - axisY) : x - axisX;
        const double rf = rhoFace(I, J, 0);
        const double share = openShareOnCutFaces ? open : 1.0;
        gravitySum += rf * gravity * share * volume * arm;
        const double pressureTorque = -(p(I, J, 0) - p(Il, Jl, 0)) / h * share * volume * arm;
        pressureSum += pressureTorque;
        if (open < 1.0) {
          pressureCutSum += pressureTorque;
          const double wall = shape.wallVelocity(c, x, y, 0.0);
          dragSum += (alpha(I, J, 0) - rf / dt) * (wall - u(I, J, 0)) * volume * arm;
          boundSum += friction.capForce(grid, c, pBed(I, J, 0), pBed(Il, Jl, 0)) * math::fabs(arm);
        }
      },
      t.gravity, t.pressure, t.pressureCut, t.wallDrag, t.wallDragBound);
  return t;
}

} // namespace hikiln::cfd

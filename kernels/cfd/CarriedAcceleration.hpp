#pragma once
/// \file CarriedAcceleration.hpp
/// \brief The incremental projection's carried acceleration (solvers/cfd/TwoPhaseSolver.hpp,
/// step 4): per face, a^n = (u^{n+1} - u_hat) / dt, what gravity and the pressure gradient of the
/// last projection did to the velocity, with the density that pressure balanced.
///
/// The momentum predictor adds rho_f a^n, so the viscous and wall stresses act on a velocity that
/// already carries the pressure's effect; the predicted velocity then has dt a^n taken off again
/// (u_hat) before gravity and the projection, which recover the whole new pressure. At a steady
/// state the predictor sees the final velocity and the balance no longer depends on dt. Unlike a
/// carried pressure gradient (grad p^n / rho^{n+1}), a^n stays bounded where the bed has just
/// left a face: there grad p^n over the gas density would accelerate the gas to metres per
/// second.
///
/// On a cut face (0 < aperture < 1) the predictor carries only the open share, aperture x a^n.
/// The projection's pressure gradient acts on the face's whole volume h^2, part of which lies in
/// the shell: the share (1 - aperture) stands for the shell's reaction, and along the face's axis
/// it has a component tangential to the shell, a torque about the axis that a real wall's normal
/// pressure cannot exert and the Coulomb cap would not limit (it carried about a fifth of a
/// drum bed's torque). Weighted by the apertures the pressure has no torque at all: the sum over
/// faces of aperture h^2 arm grad p equals minus the sum over cells of p times the aperture
/// divergence of a rigid rotation, which is 0 because a rotation has no flux through the circle
/// (ShellTorque.hpp measures it). Gravity on the face shares the weight, so a layered bed at rest
/// still needs no shell force. The shell acts on the rest of the face only through the capped
/// forcing of the momentum predictor (ProjectionKernels.hpp). At a steady state the predictor's
/// balance is therefore aperture (rho g - grad p) + shell forcing + stresses = 0 on a cut face.
///
/// Faces taking part: the open faces (aperture > 0) of component c, the last node of a periodic
/// axis included (it repeats the first: the divergence reads it, and a differing copy would make
/// the pressure problem inconsistent). Closed faces are held at the shell velocity; the boundary
/// nodes of a non-periodic axis (walls, a kiln's inflow and outflow faces) are data of the
/// momentum solve.

#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ShellGeometry.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

/// \brief Where component c's carried acceleration lives (see the file comment).
template <class MemorySpace> struct CarriedFaces {
  Field<MemorySpace> aperture;
  int offset[3];
  int hi[3];     ///< logical node range [0, hi)
  int axis;      ///< c
  int last;      ///< the last node along c
  bool boundary; ///< c's axis is not periodic: nodes 0 and last are boundary data

  CarriedFaces(CutCells<MemorySpace> const& cc, int c)
      : aperture(cc.aperture[c]), axis(c), last(cc.grid.cells(c)), boundary(!cc.periodic[c]) {
    const Grid& g = cc.grid;
    offset[0] = offset[1] = g.ghost;
    offset[2] = g.ghostZ();
    for (int a = 0; a < 3; ++a) {
      hi[a] = g.cells(a) + (a == c ? 1 : 0);
    }
  }

  /// \brief True when logical face (i, j, k) takes part.
  KOKKOS_INLINE_FUNCTION bool active(int i, int j, int k) const {
    const int n = axis == 0 ? i : (axis == 1 ? j : k);
    if (boundary && (n == 0 || n == last)) {
      return false;
    }
    return aperture(i + offset[0], j + offset[1], k + offset[2]) > 0.0;
  }
};

/// \brief rhs += rhoFace aperture accel on component c's faces (the aperture is 1 except on cut
/// faces, see the file comment). The solve's initial guess stays u^n: at a steady state
/// u* = u^n exactly, whereas u^n + dt accel would start the solve far off in a viscous bed, and
/// its stopping rule is relative to the initial residual.
template <class ExecutionSpace, class MemorySpace>
void addCarriedAcceleration(ExecutionSpace const& space, CutCells<MemorySpace> const& cc, int c,
                            Field<MemorySpace> const& rhoFace, Field<MemorySpace> const& accel,
                            Field<MemorySpace> const& rhs) {
  const CarriedFaces<MemorySpace> faces(cc, c);
  const auto open = cc.aperture[c];
  Kokkos::parallel_for(
      "hikiln::cfd::addCarriedAcceleration", gridPolicy(space, {0, 0, 0}, faces.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        if (faces.active(i, j, k)) {
          const int I = i + faces.offset[0], J = j + faces.offset[1], K = k + faces.offset[2];
          rhs(I, J, K) += rhoFace(I, J, K) * open(I, J, K) * accel(I, J, K);
        }
      });
}

/// \brief u -= dt accel on component c's faces, and accel = that u_hat (kept until
/// updateCarriedAcceleration turns it into the next acceleration).
template <class ExecutionSpace, class MemorySpace>
void removeCarriedAcceleration(ExecutionSpace const& space, CutCells<MemorySpace> const& cc, int c,
                               double dt, Field<MemorySpace> const& accel,
                               Field<MemorySpace> const& u) {
  const CarriedFaces<MemorySpace> faces(cc, c);
  Kokkos::parallel_for(
      "hikiln::cfd::removeCarriedAcceleration", gridPolicy(space, {0, 0, 0}, faces.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        if (faces.active(i, j, k)) {
          const int I = i + faces.offset[0], J = j + faces.offset[1], K = k + faces.offset[2];
          u(I, J, K) -= dt * accel(I, J, K);
          accel(I, J, K) = u(I, J, K);
        }
      });
}

/// \brief accel = (u - accel) / dt on component c's faces (accel holding u_hat), 0 elsewhere.
template <class ExecutionSpace, class MemorySpace>
void updateCarriedAcceleration(ExecutionSpace const& space, CutCells<MemorySpace> const& cc, int c,
                               double dt, Field<MemorySpace> const& u,
                               Field<MemorySpace> const& accel) {
  const CarriedFaces<MemorySpace> faces(cc, c);
  Kokkos::parallel_for(
      "hikiln::cfd::updateCarriedAcceleration", gridPolicy(space, {0, 0, 0}, faces.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + faces.offset[0], J = j + faces.offset[1], K = k + faces.offset[2];
        accel(I, J, K) = faces.active(i, j, k) ? (u(I, J, K) - accel(I, J, K)) / dt : 0.0;
      });
}

} // namespace hikiln::cfd

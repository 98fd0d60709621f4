#pragma once
/// \file DiluteFaces.hpp
/// \brief Which faces hold gas rather than bed: a face's solids fraction from its mixture
/// density, and its gas share, 1 with no solids falling to 0 at `dilutePhi`. The shell holds the
/// gas share without the Coulomb cap (WallFriction, ProjectionKernels.hpp).

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

struct DiluteFaces {
  double gasDensity = 0.0;   ///< [kg/m3]
  double solidDensity = 0.0; ///< [kg/m3]
  double dilutePhi = 0.0;    ///< solids fraction from which a face is all bed; 0: every face is

  /// \brief 1 - phi / dilutePhi clamped to [0, 1], phi the solids fraction of mixture density
  /// rhoFace; 0 everywhere when dilutePhi is 0.
  KOKKOS_INLINE_FUNCTION double gasShare(double rhoFace) const {
    if (!(dilutePhi > 0.0)) {
      return 0.0;
    }
    const double phi = (rhoFace - gasDensity) / (solidDensity - gasDensity);
    return math::fmin(1.0, math::fmax(0.0, 1.0 - phi / dilutePhi));
  }
};

} // namespace hikiln::cfd

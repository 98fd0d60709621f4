#pragma once
/// \file FitDiffusivity.hpp
/// \brief `hikiln fit-diffusivity DEM_RUN -o DIR`: the effective bed diffusivity alpha_eff of the
/// continuum energy equation (physics.md 6.3) that best reproduces the thermal mixing layer of a
/// DEM mixing run (docs/fit-diffusivity.md).
///
/// One continuum run of the DEM run's drum (diameter, rpm, fill, grain density, specific heat,
/// initial left/right temperatures taken from the DEM case) carries one temperature tracer per
/// candidate alpha_eff (the flow does not depend on temperature, so all candidates share it). At
/// every DEM snapshot time up to the fit duration both models are mapped onto the comparison grid
/// (TemperatureMaps.hpp) and compared. Misfit (the fitted measure): the rms over the snapshot
/// times t > 0 of the difference of the mixed fractions (mixing-layer area over bed area). Also
/// reported: the rms of the normalised temperature difference over blocks that are bed in both.
/// Best alpha_eff: the candidate with the smallest misfit, refined by a parabola through it and
/// its neighbours in log10(alpha_eff).
///
/// Writes fit.csv (alpha_eff, misfits), mixing_layer.csv (time, DEM and per-candidate mixed
/// fractions), fit.json (best value, measures, settings), maps.h5 (both models' block maps),
/// continuum.resolved.yaml, and PNGs via drivers/plots/plot_fit_diffusivity.py.

#include <string>
#include <vector>

namespace hikiln::fit {

/// \brief Command-line options of `hikiln fit-diffusivity`.
struct FitOptions {
  std::string demRun;
  std::string outputDirectory;
  std::string caseFile;               ///< continuum case (numerics, rheology); empty: defaults
  std::vector<std::string> overrides; ///< --set on the continuum case (after the DEM's drum)
  std::vector<double> alphas;         ///< candidates (m^2/s); empty: 1e-7 .. 1e-3, 9 values
  double duration = 30.0;             ///< s of rotation compared (snapshots up to 1 % later count)
  int blockFactor = 2;                ///< continuum cells per comparison block side
};

/// \brief Runs the fit; returns the process exit code (throws on bad input).
int runFitDiffusivity(const FitOptions& options);

} // namespace hikiln::fit

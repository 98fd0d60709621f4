#pragma once
/// \file KilnBedProfile.hpp
/// \brief The bed of a 3D kiln output, cross-section by cross-section: its depth and its surface
/// angle, and their steady-state averages compared with Kramers-Croockewit (KramersCroockewit.hpp).

#include "drivers/cfd/KramersCroockewit.hpp"
#include "kernels/cfd/Grid.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace hikiln::cfd {

/// \brief One cross-section (a layer of cells along z) of the bed.
struct BedSection {
  double z = 0.0;        ///< m from the inlet face (the layer's centre)
  double depth = 0.0;    ///< m: the depth of a flat bed of the section's bed area
  double angleDeg = 0.0; ///< surface inclination across the kiln, degrees (NaN: no surface)
};

/// \brief The bed's cross-sections of one output of `grid` (a kiln whose axis is x = y = 0 and
/// whose radius is `radius`). `volumeFraction` and `fluidVolume` are [nz][ny][nx] cell arrays
/// (phi, and the open fraction of each cell). The bed area of a section is
/// sum(phi / phiMax x fluidVolume) x hx hy: the cells' true open volume, not the cut cells'
/// raised capacities, so the shell's cut cells do not deepen the bed. The angle is the
/// least-squares line through the columns' stacked surface heights within half a radius of the
/// axis (compare::surfaceHeights), as `hikiln compare` measures the drum.
std::vector<BedSection> bedSections(Grid const& grid, std::vector<double> const& volumeFraction,
                                    std::vector<double> const& fluidVolume, double phiMax,
                                    double radius);

/// \brief What the steady-state comparison needs to know of the kiln.
struct KramersSetup {
  double length = 0.0; ///< m
  double radius = 0.0; ///< m
  double revolutionsPerSecond = 0.0;
  double slope = 0.0;       ///< rad, discharge end lower
  double damWidth = 0.0;    ///< m: sections within it of the discharge end are the dam's
  double phiMax = 0.0;      ///< bulk volume = solids volume / phiMax
  double averageFrom = 0.0; ///< s: outputs from this time on are averaged
};

/// \brief Averages the bed's sections over the outputs of a steady-state window and compares
/// the mean depth profile with Kramers-Croockewit, using the mean surface angle as the dynamic
/// angle of repose, the window's measured feed as q and the mean depth of the section nearest
/// the discharge end (the first upstream of the dam ring) as the starting depth.
class KramersComparison {
public:
  explicit KramersComparison(KramersSetup const& setup) : _setup(setup) {}

  /// \brief Adds the output at `time` (ignored before averageFrom) with the solids (m^3) fed
  /// and discharged so far.
  void add(double time, std::vector<BedSection> const& sections, double solidsIn, double solidsOut);

  /// \brief Outputs averaged so far.
  int samples() const { return _samples; }

  /// \brief Writes kramers_croockewit.csv in `out` and returns the summary block: the
  /// largest and rms relative depth deviation, and that of the depth's rise from the start to
  /// the last compared section (a note instead when there is nothing to compare).
  nlohmann::json report(std::filesystem::path const& out) const;

private:
  KramersSetup _setup;
  int _samples = 0;
  std::vector<double> _z, _depth, _angleSum;
  std::vector<int> _angleCount;
  double _t0 = 0.0, _t1 = 0.0, _in0 = 0.0, _in1 = 0.0, _out0 = 0.0, _out1 = 0.0;
};

} // namespace hikiln::cfd

#pragma once
/// \file KramersCroockewit.hpp
/// \brief The Kramers & Croockewit (1952) axial bed-depth profile of a rotary kiln, the
/// reference the 3D kiln's steady state is checked against (validation.md, "Rotary kiln axial
/// transport").

#include <vector>

namespace hikiln::cfd {

/// \brief The kiln and its bed in the equation's terms, SI units and radians.
/// With z from the discharge end towards the inlet:
///   dh/dz = tan(beta) [ (3/4) q / (pi n R^3) (2h/R - h^2/R^2)^(-3/2) - tan(alpha)/sin(beta) ].
struct KramersCroockewit {
  double radius = 0.0;               ///< R, m
  double revolutionsPerSecond = 0.0; ///< n
  double slope = 0.0;                ///< alpha, the axis' inclination (discharge end lower)
  double reposeAngle = 0.0;          ///< beta, the bed's dynamic angle of repose
  double feed = 0.0;                 ///< q, bulk volume flow of the bed, m^3/s

  /// \brief Throws std::invalid_argument naming the first parameter out of range.
  void validate() const;

  /// \brief dh/dz at depth h (0 < h < 2R).
  double depthGradient(double depth) const;

  /// \brief The depth where dh/dz = 0, the profile far from the discharge end of an inclined
  /// kiln; infinite for a horizontal one (the bed deepens all the way to the inlet) and for a
  /// feed more than the kiln carries at a half-full bed.
  double uniformDepth() const;

  /// \brief h at each of `distances` (m from the discharge end, increasing, all >= start),
  /// integrating from h(start) = startDepth with classical Runge-Kutta steps of at most
  /// `maxStep` (m). A depth past 2R (an overfilled kiln) ends the profile: NaN from there on.
  std::vector<double> profile(double start, double startDepth, std::vector<double> const& distances,
                              double maxStep = 1e-3) const;
};

} // namespace hikiln::cfd

#pragma once
/// \file KilnGeometry.hpp
/// \brief Geometry pieces of the 3D kiln (physics.md 7) for the continuum solver:
/// - KilnShell: the shell as a cylinder of finite length along z (inlet end face at zInlet,
///   discharge end at zOutlet), optionally with a dam ring, an annular weir of given radial
///   height and axial width that ends at the discharge face and turns with the shell;
/// - KilnInlet: the inlet face split into the solids feed patch (the lowest area fraction of the
///   face, a circular segment), the air patch (the highest) and the wall between them.
/// Both are plain shapes in the sense of ShellGeometry.hpp (`inside`, `wallVelocity`), so
/// buildCutCells measures the kiln, ring included, with no new code; the dam ring is switched on
/// during a run by measuring the cut cells again with damHeight > 0.

#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

/// \brief A kiln shell: DrumShell's cross-section (centre, radius, omega) between two end faces,
/// with an optional dam ring at the discharge end. The wall velocity is DrumShell's rigid
/// rotation, for the ring as well.
struct KilnShell : DrumShell {
  double zInlet = 0.0;    ///< inlet end face [m]
  double zOutlet = 1.0;   ///< discharge end face [m]
  double damHeight = 0.0; ///< radial height of the dam ring [m]; 0: no ring
  double damWidth = 0.0;  ///< axial width of the ring [m], ending at zOutlet

  /// \brief True when (x, y, z) is inside the kiln and not in the dam ring.
  KOKKOS_INLINE_FUNCTION bool inside(double x, double y, double z) const {
    if (!(z > zInlet && z < zOutlet) || !DrumShell::inside(x, y, z)) {
      return false;
    }
    return damHeight > 0.0 && z > zOutlet - damWidth ? inDischargeOpening(x, y) : true;
  }
  /// \brief True when (x, y) lies in the open part of the discharge face: inside the dam ring's
  /// opening (radius - damHeight), or the shell without a ring.
  KOKKOS_INLINE_FUNCTION bool inDischargeOpening(double x, double y) const {
    const double dx = x - cx, dy = y - cy;
    const double opening = radius - damHeight;
    return dx * dx + dy * dy < opening * opening;
  }

  /// \brief Kiln length zOutlet - zInlet.
  double length() const { return zOutlet - zInlet; }

  /// \brief Throws std::invalid_argument naming the first bad value (prefixed by who).
  void validate(std::string const& who) const {
    const auto fail = [&](char const* key, char const* why) {
      throw std::invalid_argument(who + ": " + key + " " + why);
    };
    if (!(radius > 0.0)) {
      fail("radius", "must be > 0");
    }
    if (!(zOutlet > zInlet)) {
      fail("length", "must be > 0 (discharge end beyond the inlet end)");
    }
    if (!(damHeight >= 0.0 && damHeight < radius)) {
      fail("dam_height", "must be in [0, radius)");
    }
    if (damHeight > 0.0 && !(damWidth > 0.0 && damWidth <= length())) {
      fail("dam_width", "must be in (0, length] when the dam ring is on");
    }
  }
};

/// \brief Height h above the lowest point of a circle of the given radius of the chord that
/// cuts off `fraction` of the circle's area below it. The segment below a chord at height h has
/// area R^2 (theta - sin theta) / 2, theta = 2 acos(1 - h / R); solved by bisection (the area
/// grows monotonically with h) to round-off.
inline double segmentHeight(double fraction, double radius) {
  if (!(fraction >= 0.0 && fraction <= 1.0) || !(radius > 0.0)) {
    throw std::invalid_argument("hikiln::cfd::segmentHeight: fraction must be in [0, 1] and "
                                "radius > 0");
  }
  if (fraction == 0.0 || fraction == 1.0) {
    return 2.0 * fraction * radius; // exact ends (the area is flat in h at the top)
  }
  const double pi = constants::pi;
  double lo = 0.0, hi = 2.0 * radius;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * radius; ++it) {
    const double h = 0.5 * (lo + hi);
    const double theta = 2.0 * std::acos(1.0 - h / radius);
    const double area = (theta - std::sin(theta)) / (2.0 * pi);
    (area < fraction ? lo : hi) = h;
  }
  return 0.5 * (lo + hi);
}

/// \brief The parts of the inlet face.
enum class InletPatch : int { Wall = 0, Feed = 1, Air = 2 };

/// \brief The inlet end face of a kiln split by two horizontal chords: the solids feed below
/// feedTop, the air inlet above airBottom, a stationary wall between (gravity along -y).
struct KilnInlet {
  double cx = 0.0, cy = 0.0, radius = 1.0;
  double feedTop = -1.0;     ///< y of the chord bounding the feed patch
  double airBottom = 1.0;    ///< y of the chord bounding the air patch
  double feedVelocity = 0.0; ///< axial speed of the feed [m/s]
  double airVelocity = 0.0;  ///< axial speed of the air [m/s]
  double feedPhi = 0.0;      ///< solids volume fraction carried by the feed

  /// \brief The patch that the point (x, y) of the face belongs to (Wall outside the circle).
  KOKKOS_INLINE_FUNCTION InletPatch patch(double x, double y) const {
    const double dx = x - cx, dy = y - cy;
    if (dx * dx + dy * dy >= radius * radius) {
      return InletPatch::Wall;
    }
    return y < feedTop ? InletPatch::Feed : (y > airBottom ? InletPatch::Air : InletPatch::Wall);
  }
  /// \brief Axial velocity through the face at (x, y): the patch's speed, 0 on the wall.
  KOKKOS_INLINE_FUNCTION double axialVelocity(double x, double y) const {
    const InletPatch p = patch(x, y);
    return p == InletPatch::Feed ? feedVelocity : (p == InletPatch::Air ? airVelocity : 0.0);
  }
  /// \brief Solids volume fraction flowing in at (x, y): feedPhi on the feed patch, else 0.
  KOKKOS_INLINE_FUNCTION double inflowPhi(double x, double y) const {
    return patch(x, y) == InletPatch::Feed ? feedPhi : 0.0;
  }
};

/// \brief The kiln as the continuum solver's shape with open ends (CutCellOptions::open on the
/// z sides): beyond the inlet face (z <= zInlet) only the feed and air patches are fluid, so the
/// inlet face's boundary faces are open over the patches and closed over the end wall; beyond
/// the discharge face (z >= zOutlet) the discharge opening is fluid when the outlet is open.
/// Inside, the shell with its dam ring. The grid's z range must be [zInlet, zOutlet].
struct KilnDomain {
  KilnShell shell;
  KilnInlet inlet;
  bool openOutlet = true;

  KOKKOS_INLINE_FUNCTION bool inside(double x, double y, double z) const {
    if (z <= shell.zInlet) {
      return inlet.patch(x, y) != InletPatch::Wall;
    }
    if (z >= shell.zOutlet) {
      return openOutlet && shell.DrumShell::inside(x, y, z) && shell.inDischargeOpening(x, y);
    }
    return shell.inside(x, y, z);
  }
  KOKKOS_INLINE_FUNCTION double wallVelocity(int c, double x, double y, double z) const {
    return shell.wallVelocity(c, x, y, z);
  }
};

/// \brief The inlet of `shell` whose feed patch is the lowest feedFraction of the face area and
/// whose air patch is the highest airFraction (physics.md 7: 0.046 and 0.35). Throws
/// std::invalid_argument (prefixed by who) unless both fractions are in [0, 1] and sum to at
/// most 1, and the speeds and feedPhi are >= 0.
inline KilnInlet makeKilnInlet(KilnShell const& shell, double feedFraction, double airFraction,
                               double feedVelocity, double airVelocity, double feedPhi,
                               std::string const& who) {
  const auto fail = [&](char const* key, char const* why) {
    throw std::invalid_argument(who + ": " + key + " " + why);
  };
  if (!(feedFraction >= 0.0 && feedFraction <= 1.0)) {
    fail("feed_fraction", "must be in [0, 1]");
  }
  if (!(airFraction >= 0.0 && airFraction <= 1.0)) {
    fail("air_fraction", "must be in [0, 1]");
  }
  if (!(feedFraction + airFraction <= 1.0)) {
    fail("air_fraction", "plus feed_fraction must be at most 1 (the patches would overlap)");
  }
  if (!(feedVelocity >= 0.0) || !(airVelocity >= 0.0)) {
    fail("velocity", "must be >= 0 (into the kiln)");
  }
  if (!(feedPhi >= 0.0)) {
    fail("feed_phi", "must be >= 0");
  }
  KilnInlet inlet;
  inlet.cx = shell.cx;
  inlet.cy = shell.cy;
  inlet.radius = shell.radius;
  const double bottom = shell.cy - shell.radius;
  inlet.feedTop = bottom + segmentHeight(feedFraction, shell.radius);
  inlet.airBottom = bottom + segmentHeight(1.0 - airFraction, shell.radius);
  inlet.feedVelocity = feedVelocity;
  inlet.airVelocity = airVelocity;
  inlet.feedPhi = feedPhi;
  return inlet;
}

} // namespace hikiln::cfd

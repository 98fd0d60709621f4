#pragma once
/// \file CellFieldOutput.hpp
/// \brief One field output of a continuum run (`hikiln continuum` in 2D, `hikiln kiln` in 3D):
/// host copies of cell fields and of the cell-centred velocity, written as fields_NNNN.h5 and
/// appended to fields.xmf. Arrays are [ny][nx] in 2D and [nz][ny][nx] in 3D, x fastest.

#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Xdmf.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ViscousOperator.hpp"

#include <Kokkos_Core.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief The cell fields of one output.
struct CellFieldOutput {
  std::map<std::string, std::vector<double>> scalars; ///< by dataset name (units: see .cpp)
  std::vector<double> velocity;                       ///< [cells][dims], mean of the two faces

  /// \brief Adds the interior cells of a cell field as `name` (nothing for an empty field).
  template <class MemorySpace>
  void add(std::string const& name, Field<MemorySpace> const& f, Grid const& g) {
    if (f.extent(0) == 0) {
      return;
    }
    const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, f);
    std::vector<double>& v = scalars[name];
    v.resize(static_cast<std::size_t>(g.numCells()));
    std::size_t n = 0;
    for (int k = 0; k < g.nz; ++k) {
      for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
          v[n++] = h(i + g.ghost, j + g.ghost, k + g.ghostZ());
        }
      }
    }
  }

  /// \brief Adds the fields every two-phase output carries (volume fraction, pressure, bed
  /// pressure, viscosity, strain rate, capacity) and sets the velocity, from a TwoPhaseSolver.
  template <class Solver> void addSolverFields(Solver const& solver) {
    const Grid g = solver.grid();
    add("volume_fraction", solver.volumeFraction(), g);
    add("pressure", solver.pressure(), g);
    add("bed_pressure", solver.bedPressureField(), g);
    add("viscosity", solver.viscosity(), g);
    add("strain_rate", solver.strainRate(), g);
    add("capacity", solver.cutCells().capacity, g);
    setVelocity(solver.velocity(), g);
  }

  /// \brief Sets the velocity: each component at the cell centre, the mean of its two faces.
  template <class MemorySpace>
  void setVelocity(VelocityFields<MemorySpace> const& u, Grid const& g) {
    const int dims = g.is3D() ? 3 : 2;
    velocity.assign(static_cast<std::size_t>(g.numCells()) * dims, 0.0);
    for (int c = 0; c < dims; ++c) {
      const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, u.comp[c]);
      std::size_t n = 0;
      for (int k = 0; k < g.nz; ++k) {
        for (int j = 0; j < g.ny; ++j) {
          for (int i = 0; i < g.nx; ++i) {
            const int I = i + g.ghost, J = j + g.ghost, K = k + g.ghostZ();
            const double up = h(I + (c == 0), J + (c == 1), K + (c == 2));
            velocity[dims * n++ + c] = 0.5 * (h(I, J, K) + up);
          }
        }
      }
    }
  }
};

/// \brief Writes fields_NNNN.h5 (index NNNN; the time and the grid's origin and spacing as root
/// attributes) in `out` and rewrites fields.xmf with it appended to `steps`.
void writeCellFieldOutput(std::filesystem::path const& out, int index, double time,
                          Grid const& grid, CellFieldOutput const& fields, io::RunInfo const& info,
                          std::vector<io::XdmfGridStep>& steps);

} // namespace hikiln::cfd

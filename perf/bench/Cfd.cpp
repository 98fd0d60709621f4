/// \file Cfd.cpp
/// \brief Continuum-solver benchmarks: the pressure operator's red-black Gauss-Seidel sweep and
/// operator apply as bandwidth (GB/s, to compare with copy/triad), one V-cycle, full multigrid
/// and MG-preconditioned CG solves, the viscous (MAC momentum) V-cycle, the assembled
/// Kokkos Kernels baseline (CrsMatrix SpMV and Jacobi-CG) on the same problems, and a full
/// two-phase time step in a rotating drum (cfd_drum_step: D = 2 m, 3 rpm, 20 % fill, Drucker-Prager
/// bed, dt = 5 ms; 2D sizes up to 256^2; items = cell updates), and a full step of the 3D kiln
/// with its inlet patches and open discharge (cfd_kiln_step: D = 5 m, cubic cells, 24 % bed,
/// dt = 5 ms; 32^3 and 64^3).
///
/// Problems: -div(beta grad p) = f on the unit square/cube, walls (Neumann) on every side,
/// beta from a smooth variable density (harmonic face means), random f. Sizes 64^2 .. 1024^2
/// and 32^3 .. 128^3, capped by HIKILN_BENCH_CFD_MAX_CELLS (cells per problem) or, when that is
/// unset, by HIKILN_BENCH_MAX_MIB (cells <= MiB * 2^20 / 128, so the perf smoke test stays
/// small); the Jacobi-CG baseline is further capped at 512^2 and 64^3 cells (it needs O(n)
/// iterations: minutes beyond that).
///
/// Byte counts (each array counted once per pass, 8-byte doubles, STREAM convention):
/// - smoother sweep (both colours): read x, f, beta per axis, write x: (3 + d) * 8 bytes/cell;
/// - operator apply: read x, beta per axis, write y: (2 + d) * 8 bytes/cell;
/// - SpMV: values + column indices (12 bytes per entry), row offsets, x, y.
/// A red-black half sweep touches every cache line of every array (the colours interleave), so
/// the real traffic of a sweep is up to twice the count: the GB/s are "useful" bandwidth.

#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"

#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/KilnGeometry.hpp"
#include "kernels/cfd/ViscousOperator.hpp"
#include "solvers/cfd/CellMultigrid.hpp"
#include "solvers/cfd/CrsBaseline.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <KokkosSparse_spmv.hpp>
#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace hikiln::perf {
namespace {

using cfd::Field;
using cfd::Grid;
using cfd::Staggering;

/// \brief One benchmark problem size.
struct Shape {
  int nx, ny, nz;
  std::int64_t cells() const { return static_cast<std::int64_t>(nx) * ny * nz; }
  std::string label() const {
    return nz == 1 ? std::to_string(nx) + "^2" : std::to_string(nx) + "^3";
  }
};

const std::vector<Shape>& allShapes() {
  static const std::vector<Shape> shapes = {{64, 64, 1},   {128, 128, 1},   {256, 256, 1},
                                            {512, 512, 1}, {1024, 1024, 1}, {32, 32, 32},
                                            {64, 64, 64},  {128, 128, 128}};
  return shapes;
}

/// \brief Reads a positive integer environment variable (0 when unset or invalid).
std::int64_t positiveEnv(const char* name) {
  if (const char* text = std::getenv(name)) {
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1) {
      return value;
    }
    std::cerr << "hikiln_bench: ignoring " << name << "='" << text << "'\n";
  }
  return 0;
}

/// \brief The largest problem (cells) to benchmark (see the file comment).
std::int64_t maxCells() {
  if (const std::int64_t cap = positiveEnv("HIKILN_BENCH_CFD_MAX_CELLS")) {
    return cap;
  }
  if (const std::int64_t mib = positiveEnv("HIKILN_BENCH_MAX_MIB")) {
    return mib * 1024 * 1024 / 128;
  }
  return std::int64_t{1} << 21;
}

/// \brief Indices into allShapes() within the cap (and within an extra 2D/3D cap).
std::vector<std::int64_t> shapeArgs(std::int64_t cap2d, std::int64_t cap3d) {
  std::vector<std::int64_t> args;
  const std::int64_t cap = maxCells();
  for (std::size_t i = 0; i < allShapes().size(); ++i) {
    const Shape& s = allShapes()[i];
    const std::int64_t extra = s.nz == 1 ? cap2d : cap3d;
    if (s.cells() <= cap && s.cells() <= extra) {
      args.push_back(static_cast<std::int64_t>(i));
    }
  }
  return args;
}

/// \brief A smooth inverse density varying by a factor e^2 and a reproducible pseudo-random
/// right-hand side (a hash of the cell index) in the cells of g.
template <class ExecutionSpace, class MemorySpace>
void fillProblemFields(ExecutionSpace const& space, Grid const& g, Field<MemorySpace> const& c,
                       Field<MemorySpace> const& rhs) {
  Kokkos::parallel_for(
      "hikiln::perf::cfd::setup", cfd::gridPolicy(space, {0, 0, 0}, {g.nx, g.ny, g.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const double px = g.coordinate(Staggering::Cell, 0, i);
        const double py = g.coordinate(Staggering::Cell, 1, j);
        const double pz = g.is3D() ? g.coordinate(Staggering::Cell, 2, k) : 0.0;
        c(i + g.ghost, j + g.ghost, k + g.ghostZ()) =
            math::exp(2.0 * math::sin(6.0 * px) * math::cos(4.0 * py) * (1.0 - pz));
        unsigned int h = static_cast<unsigned int>(i * 73856093) ^
                         static_cast<unsigned int>(j * 19349663) ^
                         static_cast<unsigned int>(k * 83492791);
        h = (h ^ (h >> 13)) * 0x5bd1e995u;
        h ^= h >> 15;
        rhs(i + g.ghost, j + g.ghost, k + g.ghostZ()) = static_cast<double>(h) / 4294967296.0 - 0.5;
      });
}

/// \brief The benchmark pressure problem on one backend: grid, coefficients, fields.
template <class ExecutionSpace> struct PoissonProblem {
  using memory_space = typename ExecutionSpace::memory_space;
  Grid grid;
  cfd::ScalarBoundaries bc;
  Field<memory_space> beta[3];
  Field<memory_space> x, f, y;
  cfd::CellOperator<memory_space> op;

  PoissonProblem(ExecutionSpace const& space, Shape const& shape) {
    grid =
        cfd::makeGrid(shape.nx, shape.ny, shape.nz, 1.0, 1.0, shape.nz == 1 ? 1.0 / shape.nx : 1.0);
    if (grid.is3D()) {
      bc.kind[cfd::ZLow] = bc.kind[cfd::ZHigh] = cfd::BoundaryKind::Wall;
    }
    cfd::scalarClosures(grid, bc, op.axis);
    op.grid = grid;
    // smooth density varying by a factor e^2 across the domain; random right-hand side
    const auto inverseDensity =
        cfd::makeField(space, grid, Staggering::Cell, "hikiln::perf::cfd::c");
    x = cfd::makeField(space, grid, Staggering::Cell, "hikiln::perf::cfd::x");
    f = cfd::makeField(space, grid, Staggering::Cell, "hikiln::perf::cfd::f");
    y = cfd::makeField(space, grid, Staggering::Cell, "hikiln::perf::cfd::y");
    fillProblemFields(space, grid, inverseDensity, f);
    for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
      beta[a] = cfd::makeField(space, grid, cfd::faceStaggering(a), "hikiln::perf::cfd::beta");
      op.beta[a] = beta[a];
    }
    cfd::harmonicFaceCoefficients(space, grid, op.axis, inverseDensity, beta);
    space.fence();
  }
  int dims() const { return grid.is3D() ? 3 : 2; }
};

/// \brief Labels the result with the problem size and reports cells per second.
void finish(benchmark::State& state, Shape const& shape, double cellsPerIteration) {
  state.SetLabel(shape.label());
  state.SetItemsProcessed(static_cast<std::int64_t>(cellsPerIteration) * state.iterations());
}

template <class ExecutionSpace>
void benchmarkSmoother(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  PoissonProblem<ExecutionSpace> p(space, shape);
  const double seconds = timeIterations(
      state, space, [&] { cfd::smoothCellRedBlack(space, p.op, p.x, p.f, 0, true); });
  if (!std::isfinite(cfd::maxAbsUnknowns(space, cfd::unknownBox(p.grid, p.op.axis), p.x))) {
    state.SkipWithError("smoother produced a non-finite value");
    return;
  }
  finish(state, shape, static_cast<double>(shape.cells()));
  reportBandwidth(state, (3.0 + p.dims()) * 8.0 * shape.cells(), seconds);
}

template <class ExecutionSpace>
void benchmarkApply(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  PoissonProblem<ExecutionSpace> p(space, shape);
  Kokkos::deep_copy(space, p.x, 1.0);
  const double seconds =
      timeIterations(state, space, [&] { cfd::applyCellOperator(space, p.op, p.x, p.y, false); });
  // A 1 = 0 for a pure Neumann operator: a cheap correctness check
  if (cfd::maxAbsUnknowns(space, cfd::unknownBox(p.grid, p.op.axis), p.y) > 1e-9) {
    state.SkipWithError("operator apply: A 1 != 0");
    return;
  }
  finish(state, shape, static_cast<double>(shape.cells()));
  reportBandwidth(state, (2.0 + p.dims()) * 8.0 * shape.cells(), seconds);
}

/// \brief Multigrid benchmark variants.
enum class MgRun { VCycle, Solve, Pcg };

template <class ExecutionSpace>
void benchmarkMultigrid(Backend<ExecutionSpace>, benchmark::State& state, MgRun run) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  PoissonProblem<ExecutionSpace> p(space, shape);
  cfd::MultigridOptions options;
  options.tolerance = 1e-8;
  cfd::CellMultigrid<ExecutionSpace> mg(
      space, p.grid, p.bc, Field<typename ExecutionSpace::memory_space>(), p.beta, options);
  cfd::SolveStats stats;
  const double seconds = timeIterations(state, space, [&] {
    Kokkos::deep_copy(space, p.x, 0.0);
    if (run == MgRun::VCycle) {
      mg.vcycle(p.x, p.f, true);
    } else {
      stats = run == MgRun::Solve ? mg.solve(p.x, p.f) : mg.solvePcg(p.x, p.f);
    }
  });
  (void)seconds;
  if (run != MgRun::VCycle) {
    if (!stats.converged) {
      state.SkipWithError("multigrid did not converge");
      return;
    }
    state.counters["solver_iterations"] = stats.iterations;
    state.counters["reduction"] = stats.meanReduction();
  }
  state.counters["levels"] = mg.numLevels();
  finish(state, shape, static_cast<double>(shape.cells()));
}

template <class ExecutionSpace>
void benchmarkSpmv(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  PoissonProblem<ExecutionSpace> p(space, shape);
  cfd::CrsBaseline<ExecutionSpace> crs(space, p.op);
  using vector_type = typename cfd::CrsBaseline<ExecutionSpace>::vector_type;
  vector_type xv(Kokkos::view_alloc(space, "hikiln::perf::cfd::xv"), crs.size());
  vector_type yv(Kokkos::view_alloc(space, "hikiln::perf::cfd::yv"), crs.size());
  Kokkos::deep_copy(space, xv, 1.0);
  const double seconds = timeIterations(
      state, space, [&] { KokkosSparse::spmv("N", 1.0, crs.matrix(), xv, 0.0, yv); });
  finish(state, shape, static_cast<double>(shape.cells()));
  const double bytes = 12.0 * crs.numEntries() + 4.0 * (crs.size() + 1) + 16.0 * crs.size();
  reportBandwidth(state, bytes, seconds);
  state.counters["entries"] = crs.numEntries();
}

template <class ExecutionSpace>
void benchmarkCrsCg(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  PoissonProblem<ExecutionSpace> p(space, shape);
  cfd::CrsBaseline<ExecutionSpace> crs(space, p.op);
  cfd::SolveStats stats;
  timeIterations(state, space, [&] {
    Kokkos::deep_copy(space, p.x, 0.0);
    stats = crs.solve(p.x, p.f, 1e-8, 100000);
  });
  if (!stats.converged) {
    state.SkipWithError("Jacobi-CG did not converge");
    return;
  }
  state.counters["solver_iterations"] = stats.iterations;
  finish(state, shape, static_cast<double>(shape.cells()));
}

template <class ExecutionSpace>
void benchmarkViscousVCycle(Backend<ExecutionSpace>, benchmark::State& state) {
  using memory_space = typename ExecutionSpace::memory_space;
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  const Grid g =
      cfd::makeGrid(shape.nx, shape.ny, shape.nz, 1.0, 1.0, shape.nz == 1 ? 1.0 / shape.nx : 1.0);
  cfd::VelocityBoundaries bc;
  bc.velocity[cfd::YHigh][0] = 1.0; // lid-driven box
  if (g.is3D()) {
    bc.kind[cfd::ZLow] = bc.kind[cfd::ZHigh] = cfd::BoundaryKind::Wall;
  }
  const int dims = g.is3D() ? 3 : 2;
  Field<memory_space> alpha[3];
  cfd::VelocityFields<memory_space> u, f;
  for (int c = 0; c < dims; ++c) {
    alpha[c] = cfd::makeField(space, g, cfd::faceStaggering(c), "hikiln::perf::cfd::alpha");
    Kokkos::deep_copy(space, alpha[c], 1.0e3); // rho / dt: 1000 kg/m^3 over 1 s
    u.comp[c] = cfd::makeField(space, g, cfd::faceStaggering(c), "hikiln::perf::cfd::u");
    f.comp[c] = cfd::makeField(space, g, cfd::faceStaggering(c), "hikiln::perf::cfd::f");
  }
  const auto mu = cfd::makeField(space, g, Staggering::Cell, "hikiln::perf::cfd::mu");
  Kokkos::deep_copy(space, mu, 10.0);
  cfd::ViscousMultigrid<ExecutionSpace> mg(space, g, bc, alpha, mu);
  mg.fillBoundaries(u);
  timeIterations(state, space, [&] { mg.vcycle(u, f, true); });
  state.counters["levels"] = mg.numLevels();
  finish(state, shape, static_cast<double>(shape.cells()));
}

template <class ExecutionSpace>
void benchmarkDrumStep(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  const Grid g = cfd::drumGrid(shape.nx, 2.0);
  cfd::DrumShell shell;
  shell.radius = 1.0;
  shell.omega = 3.0 * 2.0 * constants::pi / 60.0;
  cfd::TwoPhaseParameters params;
  params.rheology.m0 = 0.55;
  params.rheology.muWall = 0.35;
  cfd::TwoPhaseSolver<ExecutionSpace> solver(space, g, shell, params);
  solver.setFlatBed(-0.4); // about 20 % of the drum area
  timeIterations(state, space, [&] { solver.step(0.005); });
  finish(state, shape, static_cast<double>(shape.cells()));
}

/// A 3D kiln step (physics.md 7 set-up, scaled to the grid): D = 5 m, cubic cells, 3 rpm, 24 %
/// bed, feed (4.6 %, 0.05 m/s) and air (35 %, 2 m/s) inlet patches, open discharge.
template <class ExecutionSpace>
void benchmarkKilnStep(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const Shape shape = allShapes()[state.range(0)];
  const Grid section = cfd::drumGrid(shape.nx, 5.0);
  const Grid g =
      cfd::makeGrid(shape.nx, shape.ny, shape.nz, shape.nx * section.hx, shape.ny * section.hy,
                    shape.nz * section.hx, section.x0, section.y0, 0.0);
  cfd::KilnDomain kiln;
  kiln.shell.radius = 2.5;
  kiln.shell.omega = 3.0 * 2.0 * constants::pi / 60.0;
  kiln.shell.zOutlet = shape.nz * section.hx;
  cfd::TwoPhaseParameters params;
  params.rheology.m0 = 0.2238;
  params.rheology.m1 = 0.0827;
  params.rheology.muWall = 0.181;
  kiln.inlet = cfd::makeKilnInlet(kiln.shell, 0.046, 0.35, 0.05, 2.0, params.rheology.phiMax,
                                  "cfd_kiln_step");
  cfd::CutCellOptions cut;
  cut.periodic[2] = false;
  cfd::OpenSides ends;
  ends.kind[cfd::ZLow] = cfd::BoundaryKind::Inflow;
  ends.kind[cfd::ZHigh] = cfd::BoundaryKind::Outflow;
  cfd::TwoPhaseSolver<ExecutionSpace, cfd::KilnDomain> solver(space, g, kiln, params, cut, ends);
  solver.setFlatBed(-0.4 * kiln.shell.radius); // about 24 % of the cross-section
  solver.setInflow(kiln.inlet);
  timeIterations(state, space, [&] { solver.step(0.005); });
  finish(state, shape, static_cast<double>(shape.cells()));
}

void registerCfd() {
  const auto all = shapeArgs(std::int64_t{1} << 40, std::int64_t{1} << 40);
  const auto cgSizes = shapeArgs(512 * 512, 64 * 64 * 64);
  const auto viscousSizes = shapeArgs(1024 * 1024, 64 * 64 * 64);
  registerPerBackend("cfd_smooth_rb", all, [](auto backend, benchmark::State& state) {
    benchmarkSmoother(backend, state);
  });
  registerPerBackend("cfd_apply", all,
                     [](auto backend, benchmark::State& state) { benchmarkApply(backend, state); });
  registerPerBackend("cfd_vcycle", all, [](auto backend, benchmark::State& state) {
    benchmarkMultigrid(backend, state, MgRun::VCycle);
  });
  registerPerBackend("cfd_mg_solve", all, [](auto backend, benchmark::State& state) {
    benchmarkMultigrid(backend, state, MgRun::Solve);
  });
  registerPerBackend("cfd_mg_pcg", all, [](auto backend, benchmark::State& state) {
    benchmarkMultigrid(backend, state, MgRun::Pcg);
  });
  registerPerBackend("cfd_crs_spmv", all,
                     [](auto backend, benchmark::State& state) { benchmarkSpmv(backend, state); });
  registerPerBackend("cfd_crs_jacobi_cg", cgSizes,
                     [](auto backend, benchmark::State& state) { benchmarkCrsCg(backend, state); });
  registerPerBackend("cfd_viscous_vcycle", viscousSizes, [](auto backend, benchmark::State& state) {
    benchmarkViscousVCycle(backend, state);
  });
  registerPerBackend(
      "cfd_drum_step", shapeArgs(256 * 256, 0),
      [](auto backend, benchmark::State& state) { benchmarkDrumStep(backend, state); });
  registerPerBackend(
      "cfd_kiln_step", shapeArgs(0, 64 * 64 * 64),
      [](auto backend, benchmark::State& state) { benchmarkKilnStep(backend, state); });
}

HIKILN_PERF_REGISTER(registerCfd);

} // namespace
} // namespace hikiln::perf

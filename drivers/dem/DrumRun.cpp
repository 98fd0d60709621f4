#include "drivers/dem/DrumRun.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/dem/DemCase.hpp"
#include "drivers/dem/DemCheckpoint.hpp"
#include "drivers/dem/DrumAverages.hpp"
#include "drivers/dem/DrumHeat.hpp"
#include "drivers/dem/ParticleSnapshots.hpp"
#include "drivers/dem/TimeSeries.hpp"
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Summary.hpp"
#include "drivers/log/Progress.hpp"
#include "solvers/dem/DrumAnalysis.hpp"

#include <Kokkos_Core.hpp>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace hikiln::dem {

namespace fs = std::filesystem;
using Space = Kokkos::DefaultExecutionSpace;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Running mean and spread of a sampled bed measure (NaN samples are skipped).
struct Running {
  double sum = 0, sumSq = 0;
  std::int64_t n = 0;
  void add(double v) {
    if (std::isfinite(v))
      sum += v, sumSq += v * v, ++n;
  }
  double mean() const { return n ? sum / n : std::nan(""); }
  double std() const { return n > 1 ? std::sqrt(std::max(0.0, sumSq / n - mean() * mean())) : 0; }
  void save(io::Checkpoint& c, const std::string& name) const {
    c.scalars[name + "_sum"] = sum;
    c.scalars[name + "_sumsq"] = sumSq;
    c.scalars[name + "_n"] = static_cast<double>(n);
  }
  void load(const io::Checkpoint& c, const std::string& name) {
    sum = c.scalars.at(name + "_sum");
    sumSq = c.scalars.at(name + "_sumsq");
    n = static_cast<std::int64_t>(c.scalars.at(name + "_n"));
  }
};

/// Settles for at least `duration`, then on until the bed is at rest (mean kinetic energy per
/// particle below 1e-4 m g d, i.e. speeds around 1 % of sqrt(g d)), at most 10 x `duration`.
void settle(DemSystem<Space>& system, double duration, double gravity, const char* label) {
  const auto host = system.hostParticles();
  double massSum = 0, diameterSum = 0;
  for (std::size_t i = 0; i < host.count(); ++i)
    massSum += host.mass(i), diameterSum += 2 * host.radius(i);
  const double n = static_cast<double>(std::max<std::size_t>(1, host.count()));
  const double restEnergy = 1e-4 * (massSum / n) * gravity * (diameterSum / n) * n;
  const double start = system.time();
  log::Progress progress(label, start + duration);
  const auto chunk = std::max<std::int64_t>(1, std::llround(0.05 / system.timeStep()));
  double kinetic = 0;
  do {
    system.advance(chunk);
    progress.update(system.time(), system.stepCount());
    kinetic = system.energy().kinetic();
  } while (system.time() - start < 10 * duration &&
           (system.time() - start < duration || !(kinetic < restEnergy)));
  progress.finish();
  spdlog::info("{}: {:.2f} s, kinetic energy {:.3g} J ({}at rest)", label, system.time() - start,
               kinetic, kinetic < restEnergy ? "" : "NOT ");
}

void requireFinite(const DemSystem<Space>& system, const std::string& where) {
  const double ke = system.energy().kinetic();
  if (!std::isfinite(ke)) {
    throw std::runtime_error(fmt::format(
        "the DEM state became NaN/inf at t = {:.4f} s ({}); lower time.step_safety or check the "
        "contact parameters; the last checkpoint in the output directory is intact",
        system.time(), where));
  }
}

/// Particle counts {"free", "fixed", "shell"} (ParticleKind) for summary.json.
nlohmann::json particleKindCounts(const ParticleArrays<Kokkos::HostSpace>& host) {
  std::int64_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < host.count(); ++i)
    ++counts[std::min<int>(host.kind(i), 2)];
  return {{"free", counts[0]}, {"fixed", counts[1]}, {"shell", counts[2]}};
}

/// Puts the particles (with their shapes, for blocky ones) into the system.
void setDrumParticles(DemSystem<Space>& system, const DrumParticles& d) {
  if (d.blocky())
    system.setParticles(d.particles, d.shapes);
  else
    system.setParticles(d.particles);
}

/// The system's particles with their current shapes and orientations.
DrumParticles currentParticles(const DemSystem<Space>& system) {
  return {system.hostParticles(), system.hostShapes()};
}

/// summary.json "particle_shape".
nlohmann::json particleShapeSummary(const FillSpec& fill) {
  if (!fill.shape.superquadric)
    return {{"shape", "disc"}, {"size", "particles.diameter is the disc diameter"}};
  return {{"shape", "superquadric"},
          {"blockiness", fill.shape.blockiness},
          {"aspect_ratio", fill.shape.aspectRatio},
          {"bounding_over_equal_area_radius", boundingRadiusRatio(fill.shape)},
          {"size", "particles.diameter is the equal-area diameter d (area pi d^2/4); radius in "
                   "snapshots and checkpoints is the bounding radius"}};
}

std::string describeShape(const FillSpec& fill) {
  if (!fill.shape.superquadric)
    return "discs";
  return fmt::format("superquadrics N = {:g}, aspect ratio {:g} (equal-area diameter {:g} m, "
                     "bounding radius {:.4f} x d/2)",
                     fill.shape.blockiness, fill.shape.aspectRatio, fill.meanDiameter,
                     boundingRadiusRatio(fill.shape));
}

} // namespace

int runDrum(const DrumRunOptions& o) {
  const auto wallStart = Clock::now();
  const auto file = cases::CaseFile::load(o.caseFile, demSchema(), o.overrides);
  const DrumRunSettings s = drumSettingsFromCase(file);
  const fs::path out(o.outputDirectory);
  fs::create_directories(out);
  const std::string checkpointPath = (out / "checkpoint.h5").string();
  const io::RunInfo info{"dem", app::defaultBackend(), file.resolvedYaml()};
  const double R = s.fill.drumRadius;

  DemSystem<Space> system(s.config);
  DrumAverages averages(s, out.string(), info);
  DrumHeat heat(s.heat, out.string());
  Running slip, angle;
  std::int64_t rotationStartStep = 0;
  double rotationStartTime = 0, fillMeasured = 0, bulkFraction = 0, settleWall = 0;
  TimeSeries series((out / "timeseries.csv").string(),
                    {"time", "rotation_time", "kinetic_energy", "wall_slip", "surface_angle_deg"});
  double restartTime = -1;

  if (o.restart) {
    const io::Checkpoint cp = io::readCheckpoint(checkpointPath);
    // Only time.duration may differ: a restart can extend a run, not change its physics.
    const std::vector<std::string> mayChange = {"time.duration"};
    const auto saved =
        cases::CaseFile::fromString(cp.resolvedCaseYaml, checkpointPath, demSchema());
    if (saved.valuesText(mayChange) != file.valuesText(mayChange)) {
      throw std::runtime_error(
          fmt::format("{}: the case differs from the one the checkpoint {} was written with (only "
                      "time.duration may change on a restart); see {}/case.resolved.yaml",
                      o.caseFile, checkpointPath, o.outputDirectory));
    }
    system.setDrumAngularVelocity(s.omega());
    system.importState(fromCheckpoint(cp));
    slip.load(cp, "slip");
    angle.load(cp, "angle");
    rotationStartStep = static_cast<std::int64_t>(cp.scalars.at("rotation_start_step"));
    rotationStartTime = cp.scalars.at("rotation_start_time");
    fillMeasured = cp.scalars.at("fill_measured");
    bulkFraction = cp.scalars.at("bulk_fraction");
    averages.resume(cp, system.hostParticles(), fillMeasured);
    heat.resume(cp, system);
    restartTime = cp.time;
    series.keepUntil(restartTime);
    spdlog::info("restarting from {} at t = {:.3f} s (step {})", checkpointPath, cp.time, cp.step);
  } else {
    file.writeResolved((out / "case.resolved.yaml").string());
    const auto t0 = Clock::now();
    setDrumParticles(system, generateDrumParticles(s.fill));
    spdlog::info("filling: {} {} on a lattice, dt = {:.3g} s, settling {} s", system.size(),
                 describeShape(s.fill), system.timeStep(), s.settleTime);
    settle(system, s.settleTime, -s.config.gravityY, "settle");
    // Trimming lets the bed compact (its bulk fraction rises), so trim with a margin first, then
    // to the requested fill with the bulk fraction measured after the first trim.
    const double margins[] = {1.08, 1.0};
    for (double margin : margins) {
      const DrumParticles current = currentParticles(system);
      const BedMeasurement now = measureBed(current.particles, R, current.shapes);
      setDrumParticles(system, trimToFill(current, R, margin * s.fill.fill, now.bulkFraction));
      settle(system, 0.5 * s.settleTime, -s.config.gravityY, "settle after trim");
    }
    requireFinite(system, "settling");
    const DrumParticles settled = currentParticles(system);
    const BedMeasurement bed = measureBed(settled.particles, R, settled.shapes);
    fillMeasured = bed.fill;
    bulkFraction = bed.bulkFraction;
    averages.start(system.hostParticles(), fillMeasured);
    settleWall = secondsSince(t0);
    spdlog::info(
        "bed: {} particles, fill {:.2f} % (requested {:.2f} %), bulk solid fraction {:.3f}",
        bed.count, 100 * bed.fill, 100 * s.fill.fill, bed.bulkFraction);
    rotationStartStep = system.stepCount();
    rotationStartTime = system.time();
    system.setDrumAngularVelocity(s.omega());
    heat.start(system, 0.0); // temperatures start with the rotation
  }

  std::vector<std::string> snapshotFieldNames = heat.snapshotFieldNames();
  if (system.blocky()) {
    const auto names = shapeFieldNames();
    snapshotFieldNames.insert(snapshotFieldNames.end(), names.begin(), names.end());
  }
  ParticleSnapshots snapshots(out.string(), info, restartTime, snapshotFieldNames);
  // heat fields and, for blocky particles, the orientations and shapes
  const auto snapshotFields = [&](const ParticleArrays<Kokkos::HostSpace>& host) {
    std::vector<ParticleField> fields = heat.snapshotFields(host);
    for (ParticleField& f : shapeFields(system.hostShapes(), host.count()))
      fields.push_back(std::move(f));
    return fields;
  };
  const double dt = system.timeStep();
  const auto everyN = [dt](double interval) {
    return std::max<std::int64_t>(1, std::llround(interval / dt));
  };
  const std::int64_t totalSteps = std::llround(s.duration / dt);
  const std::int64_t sampleEvery = everyN(s.sampleInterval);
  const std::int64_t snapshotEvery = everyN(s.snapshotInterval);
  const std::int64_t checkpointEvery = everyN(s.checkpointInterval);
  const std::int64_t averageEvery = everyN(s.averageInterval);
  const std::int64_t spinUpSteps = std::llround(s.spinUp / dt);
  if (!o.restart) {
    const auto host = system.hostParticles();
    snapshots.write(system.stepCount(), system.time(), host, snapshotFields(host));
  }

  const auto rotateStart = Clock::now();
  const std::int64_t firstStep = system.stepCount();
  log::Progress progress("rotate", s.duration);
  std::int64_t k = system.stepCount() - rotationStartStep;
  while (k < totalSteps) {
    const std::int64_t n = std::min(sampleEvery - k % sampleEvery, totalSteps - k);
    heat.advance(system, n); // the system's steps, with the heat steps due
    k += n;
    progress.update(static_cast<double>(k) * dt, system.stepCount());
    if (k % sampleEvery == 0) { // a fixed schedule, so a restart samples the same steps
      requireFinite(system, "rotation");
      const auto host = system.hostParticles();
      const double sl = wallSlip(host, R, s.omega());
      const double an = surfaceAngleDegrees(host);
      if (k >= spinUpSteps) {
        slip.add(sl), angle.add(an);
        averages.sample(system, static_cast<double>(k) * dt);
        if (heat.enabled())
          averages.sampleTemperature(host, heat.meanTemperatures(host));
      }
      series.add({system.time(), static_cast<double>(k) * dt, system.energy().kinetic(), sl, an});
      heat.sample(system, static_cast<double>(k) * dt);
      // the first sample on or past each interval, counted from the previous sample (not from
      // k - n: a restart from a checkpoint between samples must pick the same samples)
      if ((k - sampleEvery) / snapshotEvery != k / snapshotEvery)
        snapshots.write(system.stepCount(), system.time(), host, snapshotFields(host));
    }
    // cumulative averages.h5 at the first step on or past each interval (k moves in sample steps)
    if (k >= spinUpSteps && ((k - n) / averageEvery != k / averageEvery || k == totalSteps))
      averages.write(static_cast<double>(k) * dt);
    // Steps advance a sample interval at a time: act on the first step on or past each interval.
    if ((k - n) / checkpointEvery != k / checkpointEvery || k == totalSteps) {
      io::Checkpoint cp = toCheckpoint(system.exportState(), "dem");
      cp.resolvedCaseYaml = file.resolvedYaml();
      slip.save(cp, "slip");
      angle.save(cp, "angle");
      averages.save(cp);
      heat.save(cp);
      cp.scalars["rotation_start_step"] = static_cast<double>(rotationStartStep);
      cp.scalars["rotation_start_time"] = rotationStartTime;
      cp.scalars["fill_measured"] = fillMeasured;
      cp.scalars["bulk_fraction"] = bulkFraction;
      io::writeCheckpoint(checkpointPath, cp);
      series.flush();
      heat.flush();
    }
  }
  progress.finish();
  Kokkos::fence();
  const double rotateWall = secondsSince(rotateStart);
  const double particleSteps =
      static_cast<double>(system.stepCount() - firstStep) * static_cast<double>(system.size());

  nlohmann::json summary;
  summary["stage"] = "dem";
  summary["case"] = o.caseFile;
  summary["backend"] = app::defaultBackend();
  summary["threads"] = Space::concurrency();
  summary["restarted"] = o.restart;
  summary["particles"] = system.size(); // glued shell discs included
  summary["particle_shape"] = particleShapeSummary(s.fill);
  summary["particles_by_kind"] = particleKindCounts(system.hostParticles());
  summary["fill_requested"] = s.fill.fill;
  summary["fill_measured"] = fillMeasured;
  summary["bulk_solid_fraction"] = bulkFraction;
  summary["time_step_s"] = dt;
  summary["steps_total"] = system.stepCount();
  summary["rotation_steps"] = totalSteps;
  summary["simulated_rotation_s"] = s.duration;
  summary["rpm"] = s.rpm;
  summary["froude"] = s.omega() * s.omega() * R / std::max(1e-300, -s.config.gravityY);
  summary["wall_time_s"] = secondsSince(wallStart);
  summary["settle_wall_time_s"] = settleWall;
  summary["rotate_wall_time_s"] = rotateWall;
  summary["particle_steps_per_s"] = rotateWall > 0 ? particleSteps / rotateWall : 0.0;
  summary["neighbor_rebuilds"] = system.rebuildCount();
  summary["wall_slip_percent"] = 100 * slip.mean();
  summary["wall_slip_std_percent"] = 100 * slip.std();
  summary["surface_angle_deg"] = angle.mean();
  summary["surface_angle_std_deg"] = angle.std();
  summary["bed_samples"] = slip.n;
  summary["averages_from_s"] = s.spinUp;
  summary["kinetic_energy_final_J"] = system.energy().kinetic();
  summary["snapshots"] = snapshots.size();
  summary["averages"] = averages.summary();
  summary["heat"] = heat.summary();
  io::writeSummaryJson((out / "summary.json").string(), summary);
  averages.plot();
  heat.plot(R);
  spdlog::info("dem: {} particles, {:.1f} s rotated in {:.1f} s wall ({:.3g} particle-steps/s); "
               "wall slip {:.1f} %, surface angle {:.1f} deg; outputs in {}",
               system.size(), s.duration, rotateWall, summary["particle_steps_per_s"].get<double>(),
               100 * slip.mean(), angle.mean(), o.outputDirectory);
  return 0;
}

} // namespace hikiln::dem

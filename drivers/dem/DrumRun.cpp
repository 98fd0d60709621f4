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
#include "solvers/dem/DemBatch.hpp"
#include "solvers/dem/DrumAnalysis.hpp"

#include <Kokkos_Core.hpp>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
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
/// damping (1/s, time.settle_damping): after each chunk of about 0.05 s the free particles' motion
/// is multiplied by exp(-damping x chunk), which brings a tall bed in a large drum to rest sooner.
void settle(DemSystem<Space>& system, double duration, double gravity, double damping,
            const char* label) {
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
    if (damping > 0)
      system.scaleFreeMotion(std::exp(-damping * static_cast<double>(chunk) * system.timeStep()));
    kinetic = system.energy().kinetic();
    // past the minimum the loop waits for rest: say how far the bed is from it
    std::string note;
    if (system.time() - start >= duration) {
      note = restEnergy > 0
                 ? fmt::format("waiting for rest: kinetic energy {:.3g} x the rest level",
                               kinetic / restEnergy)
                 : std::string("no rest level without gravity");
      note += fmt::format(" (at most until t = {:.3f} s)", start + 10 * duration);
    }
    progress.update(system.time(), system.stepCount(), note);
  } while (system.time() - start < 10 * duration &&
           (system.time() - start < duration || !(kinetic < restEnergy)));
  progress.finish();
  const bool rest = kinetic < restEnergy;
  spdlog::info("{}: {:.2f} s, kinetic energy {:.3g} J ({}at rest){}", label, system.time() - start,
               kinetic, rest ? "" : "NOT ",
               rest || damping > 0 ? ""
                                   : "; time.settle_damping brings a large bed to rest sooner");
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

fs::path createdDirectory(const std::string& path) {
  fs::create_directories(path);
  return path;
}

/// One drum slice: the case loaded and the bed set up (or restored from the checkpoint) by the
/// constructor; then the rotation in chunks that end on the sample schedule, each chunk advanced
/// by advanceAlone() (`hikiln dem`) or by a DemBatch with the others of a sweep, followed by
/// afterSteps() (samples, snapshots, averages, checkpoints); finally finish() (summary, plots).
class DrumSlice {
public:
  explicit DrumSlice(const DrumRunOptions& o)
      : _o(o), _file(cases::CaseFile::load(o.caseFile, demSchema(), o.overrides)),
        _s(drumSettingsFromCase(_file)),
        _out(createdDirectory(o.outputDirectory)), _info{"dem", app::defaultBackend(),
                                                         _file.resolvedYaml()},
        _R(_s.fill.drumRadius), _system(_s.config), _averages(_s, _out.string(), _info),
        _heat(_s.heat, _out.string()),
        _series((_out / "timeseries.csv").string(),
                {"time", "rotation_time", "kinetic_energy", "wall_slip", "surface_angle_deg"}) {
    if (o.restart)
      restore();
    else
      setUp();
    std::vector<std::string> snapshotFieldNames = _heat.snapshotFieldNames();
    if (_system.blocky()) {
      const auto names = shapeFieldNames();
      snapshotFieldNames.insert(snapshotFieldNames.end(), names.begin(), names.end());
    }
    _snapshots =
        std::make_unique<ParticleSnapshots>(_out.string(), _info, _restartTime, snapshotFieldNames);
    const double dt = _system.timeStep();
    const auto everyN = [dt](double interval) {
      return std::max<std::int64_t>(1, std::llround(interval / dt));
    };
    _totalSteps = std::llround(_s.duration / dt);
    _sampleEvery = everyN(_s.sampleInterval);
    _snapshotEvery = everyN(_s.snapshotInterval);
    _checkpointEvery = everyN(_s.checkpointInterval);
    _averageEvery = everyN(_s.averageInterval);
    _spinUpSteps = std::llround(_s.spinUp / dt);
    if (!o.restart) {
      const auto host = _system.hostParticles();
      _snapshots->write(_system.stepCount(), _system.time(), host, snapshotFields(host));
    }
    _firstStep = _system.stepCount();
    _k = _system.stepCount() - _rotationStartStep;
    _progress = std::make_unique<log::Progress>("rotate", _s.duration);
  }

  DemSystem<Space>& system() { return _system; }
  const DrumRunOptions& options() const { return _o; }
  /// \brief True while rotation steps remain.
  bool rotating() const { return _k < _totalSteps; }
  /// \brief Steps to the next sample (or the end of the run).
  std::int64_t stepsToNextSample() const {
    return std::min(_sampleEvery - _k % _sampleEvery, _totalSteps - _k);
  }
  /// \brief Advances the slice's own system by n steps, with the heat steps due.
  void advanceAlone(std::int64_t n) { _heat.advance(_system, n); }
  /// \brief Why this slice cannot join a batch (empty: it can).
  std::string whyNotBatchable() const {
    return _heat.enabled() ? "heat transfer is on" : DemBatch<Space>::refusal(_system);
  }

  /// \brief Sampling, snapshots, averages and checkpoints due after n steps were taken.
  void afterSteps(std::int64_t n) {
    const double dt = _system.timeStep();
    _k += n;
    _progress->update(static_cast<double>(_k) * dt, _system.stepCount());
    if (_k % _sampleEvery == 0) { // a fixed schedule, so a restart samples the same steps
      requireFinite(_system, "rotation");
      const auto host = _system.hostParticles();
      const double sl = wallSlip(host, _R, _s.omega());
      const double an = surfaceAngleDegrees(host);
      if (_k >= _spinUpSteps) {
        _slip.add(sl), _angle.add(an);
        _averages.sample(_system, static_cast<double>(_k) * dt);
        if (_heat.enabled())
          _averages.sampleTemperature(host, _heat.meanTemperatures(host));
      }
      _series.add(
          {_system.time(), static_cast<double>(_k) * dt, _system.energy().kinetic(), sl, an});
      _heat.sample(_system, static_cast<double>(_k) * dt);
      // the first sample on or past each interval, counted from the previous sample (not from
      // k - n: a restart from a checkpoint between samples must pick the same samples)
      if ((_k - _sampleEvery) / _snapshotEvery != _k / _snapshotEvery)
        _snapshots->write(_system.stepCount(), _system.time(), host, snapshotFields(host));
    }
    // cumulative averages.h5 at the first step on or past each interval (k moves in sample steps)
    if (_k >= _spinUpSteps && ((_k - n) / _averageEvery != _k / _averageEvery || _k == _totalSteps))
      _averages.write(static_cast<double>(_k) * dt);
    // Steps advance a sample interval at a time: act on the first step on or past each interval.
    if ((_k - n) / _checkpointEvery != _k / _checkpointEvery || _k == _totalSteps)
      checkpoint();
  }

  /// \brief summary.json and plots; rotateWall is the wall time of the rotation (of the whole
  /// batch for a batched slice, described by `batch`).
  void finish(double rotateWall, const nlohmann::json& batch = nullptr) {
    _progress->finish();
    Kokkos::fence();
    const double dt = _system.timeStep();
    const double particleSteps =
        static_cast<double>(_system.stepCount() - _firstStep) * static_cast<double>(_system.size());
    nlohmann::json summary;
    summary["stage"] = "dem";
    summary["case"] = _o.caseFile;
    summary["backend"] = app::defaultBackend();
    summary["threads"] = Space::concurrency();
    summary["restarted"] = _o.restart;
    summary["particles"] = _system.size(); // glued shell discs included
    summary["particle_shape"] = particleShapeSummary(_s.fill);
    summary["particles_by_kind"] = particleKindCounts(_system.hostParticles());
    summary["fill_requested"] = _s.fill.fill;
    summary["fill_measured"] = _fillMeasured;
    summary["bulk_solid_fraction"] = _bulkFraction;
    summary["time_step_s"] = dt;
    summary["steps_total"] = _system.stepCount();
    summary["rotation_steps"] = _totalSteps;
    summary["simulated_rotation_s"] = _s.duration;
    summary["rpm"] = _s.rpm;
    summary["froude"] = _s.omega() * _s.omega() * _R / std::max(1e-300, -_s.config.gravityY);
    summary["wall_time_s"] = secondsSince(_wallStart);
    summary["settle_wall_time_s"] = _settleWall;
    summary["rotate_wall_time_s"] = rotateWall;
    // a batched slice shares its wall time: its rate is the batch's (summed over the slices)
    summary["particle_steps_per_s"] = batch.is_null()
                                          ? (rotateWall > 0 ? particleSteps / rotateWall : 0.0)
                                          : batch["particle_steps_per_s"].get<double>();
    summary["batch"] = batch;
    summary["neighbor_rebuilds"] = _system.rebuildCount();
    summary["wall_slip_percent"] = 100 * _slip.mean();
    summary["wall_slip_std_percent"] = 100 * _slip.std();
    summary["surface_angle_deg"] = _angle.mean();
    summary["surface_angle_std_deg"] = _angle.std();
    summary["bed_samples"] = _slip.n;
    summary["averages_from_s"] = _s.spinUp;
    summary["kinetic_energy_final_J"] = _system.energy().kinetic();
    summary["snapshots"] = _snapshots->size();
    summary["averages"] = _averages.summary();
    summary["heat"] = _heat.summary();
    io::writeSummaryJson((_out / "summary.json").string(), summary);
    _averages.plot();
    _heat.plot(_R);
    spdlog::info(
        "dem: {} particles, {:.1f} s rotated in {:.1f} s wall ({:.3g} particle-steps/s{}); "
        "wall slip {:.1f} %, surface angle {:.1f} deg; outputs in {}",
        _system.size(), _s.duration, rotateWall, summary["particle_steps_per_s"].get<double>(),
        batch.is_null() ? "" : ", batch", 100 * _slip.mean(), _angle.mean(), _o.outputDirectory);
  }

private:
  void restore() {
    const std::string checkpointPath = (_out / "checkpoint.h5").string();
    const io::Checkpoint cp = io::readCheckpoint(checkpointPath);
    // Only time.duration may differ: a restart can extend a run, not change its physics.
    const std::vector<std::string> mayChange = {"time.duration"};
    const auto saved =
        cases::CaseFile::fromString(cp.resolvedCaseYaml, checkpointPath, demSchema());
    if (saved.valuesText(mayChange) != _file.valuesText(mayChange)) {
      throw std::runtime_error(
          fmt::format("{}: the case differs from the one the checkpoint {} was written with (only "
                      "time.duration may change on a restart); see {}/case.resolved.yaml",
                      _o.caseFile, checkpointPath, _o.outputDirectory));
    }
    _system.setDrumAngularVelocity(_s.omega());
    _system.importState(fromCheckpoint(cp));
    _slip.load(cp, "slip");
    _angle.load(cp, "angle");
    _rotationStartStep = static_cast<std::int64_t>(cp.scalars.at("rotation_start_step"));
    _rotationStartTime = cp.scalars.at("rotation_start_time");
    _fillMeasured = cp.scalars.at("fill_measured");
    _bulkFraction = cp.scalars.at("bulk_fraction");
    _averages.resume(cp, _system.hostParticles(), _fillMeasured);
    _heat.resume(cp, _system);
    _restartTime = cp.time;
    _series.keepUntil(_restartTime);
    spdlog::info("restarting from {} at t = {:.3f} s (step {})", checkpointPath, cp.time, cp.step);
  }

  void setUp() {
    _file.writeResolved((_out / "case.resolved.yaml").string());
    const auto t0 = Clock::now();
    setDrumParticles(_system, generateDrumParticles(_s.fill));
    spdlog::info("filling: {} {} on a lattice, dt = {:.3g} s, settling {} s", _system.size(),
                 describeShape(_s.fill), _system.timeStep(), _s.settleTime);
    settle(_system, _s.settleTime, -_s.config.gravityY, _s.settleDamping, "settle");
    // Trimming lets the bed compact (its bulk fraction rises), so trim with a margin first, then
    // to the requested fill with the bulk fraction measured after the first trim.
    const double margins[] = {1.08, 1.0};
    for (double margin : margins) {
      const DrumParticles current = currentParticles(_system);
      const BedMeasurement now = measureBed(current.particles, _R, current.shapes);
      setDrumParticles(_system, trimToFill(current, _R, margin * _s.fill.fill, now.bulkFraction));
      settle(_system, 0.5 * _s.settleTime, -_s.config.gravityY, _s.settleDamping,
             "settle after trim");
    }
    requireFinite(_system, "settling");
    const DrumParticles settled = currentParticles(_system);
    const BedMeasurement bed = measureBed(settled.particles, _R, settled.shapes);
    _fillMeasured = bed.fill;
    _bulkFraction = bed.bulkFraction;
    _averages.start(_system.hostParticles(), _fillMeasured);
    _settleWall = secondsSince(t0);
    spdlog::info(
        "bed: {} particles, fill {:.2f} % (requested {:.2f} %), bulk solid fraction {:.3f}",
        bed.count, 100 * bed.fill, 100 * _s.fill.fill, bed.bulkFraction);
    _rotationStartStep = _system.stepCount();
    _rotationStartTime = _system.time();
    _system.setDrumAngularVelocity(_s.omega());
    _heat.start(_system, 0.0); // temperatures start with the rotation
  }

  // heat fields and, for blocky particles, the orientations and shapes
  std::vector<ParticleField> snapshotFields(const ParticleArrays<Kokkos::HostSpace>& host) const {
    std::vector<ParticleField> fields = _heat.snapshotFields(host);
    for (ParticleField& f : shapeFields(_system.hostShapes(), host.count()))
      fields.push_back(std::move(f));
    return fields;
  }

  void checkpoint() {
    io::Checkpoint cp = toCheckpoint(_system.exportState(), "dem");
    cp.resolvedCaseYaml = _file.resolvedYaml();
    _slip.save(cp, "slip");
    _angle.save(cp, "angle");
    _averages.save(cp);
    _heat.save(cp);
    cp.scalars["rotation_start_step"] = static_cast<double>(_rotationStartStep);
    cp.scalars["rotation_start_time"] = _rotationStartTime;
    cp.scalars["fill_measured"] = _fillMeasured;
    cp.scalars["bulk_fraction"] = _bulkFraction;
    io::writeCheckpoint((_out / "checkpoint.h5").string(), cp);
    _series.flush();
    _heat.flush();
  }

  Clock::time_point _wallStart = Clock::now();
  DrumRunOptions _o;
  cases::CaseFile _file;
  DrumRunSettings _s;
  fs::path _out;
  io::RunInfo _info;
  double _R;
  DemSystem<Space> _system;
  DrumAverages _averages;
  DrumHeat _heat;
  TimeSeries _series;
  Running _slip, _angle;
  std::unique_ptr<ParticleSnapshots> _snapshots;
  std::unique_ptr<log::Progress> _progress;
  std::int64_t _rotationStartStep = 0;
  double _rotationStartTime = 0, _fillMeasured = 0, _bulkFraction = 0, _settleWall = 0;
  double _restartTime = -1;
  std::int64_t _totalSteps = 0, _sampleEvery = 1, _snapshotEvery = 1, _checkpointEvery = 1;
  std::int64_t _averageEvery = 1, _spinUpSteps = 0, _firstStep = 0, _k = 0;
};

/// Rotates the slices as one DemBatch: each chunk of steps ends at the next sample of any slice;
/// every slice's state then goes back to its own system (importState() continues bitwise), which
/// samples, writes and checkpoints as it would alone. Finished slices leave the batch (rebuilt
/// from the others' states).
void runBatched(std::vector<DrumSlice*> active) {
  const auto start = Clock::now();
  const std::size_t sliceCount = active.size();
  std::vector<DrumSlice*> finished;
  double particleSteps = 0;
  while (!active.empty()) {
    DemBatch<Space> batch;
    for (DrumSlice* s : active)
      batch.add(s->system());
    batch.start();
    spdlog::info("batch: {} slices, {} particles, dt = {:.3g} s", batch.sliceCount(), batch.size(),
                 batch.timeStep());
    std::vector<DrumSlice*> rotating;
    for (;;) {
      std::int64_t n = std::numeric_limits<std::int64_t>::max();
      for (DrumSlice* s : active)
        n = std::min(n, s->stepsToNextSample());
      batch.advance(n);
      particleSteps += static_cast<double>(n) * static_cast<double>(batch.size());
      const std::vector<DemState> states = batch.exportSlices();
      rotating.clear();
      for (std::size_t k = 0; k < active.size(); ++k) {
        active[k]->system().importState(states[k]);
        active[k]->afterSteps(n);
        (active[k]->rotating() ? rotating : finished).push_back(active[k]);
      }
      if (rotating.size() != active.size())
        break; // a slice finished: the batch goes on without it
    }
    active = rotating;
  }
  const double wall = secondsSince(start);
  const nlohmann::json batch = {{"slices", sliceCount},
                                {"rotate_wall_time_s", wall},
                                {"particle_steps_per_s", wall > 0 ? particleSteps / wall : 0.0}};
  for (DrumSlice* s : finished)
    s->finish(wall, batch);
}

} // namespace

int runDrum(const DrumRunOptions& o) {
  DrumSlice slice(o);
  const auto rotateStart = Clock::now();
  while (slice.rotating()) {
    const std::int64_t n = slice.stepsToNextSample();
    slice.advanceAlone(n);
    slice.afterSteps(n);
  }
  slice.finish(secondsSince(rotateStart));
  return 0;
}

int runDrumBatch(const std::vector<DrumRunOptions>& runs) {
  std::vector<std::unique_ptr<DrumSlice>> slices;
  for (const DrumRunOptions& o : runs) {
    spdlog::info("batch: setting up {}", o.outputDirectory);
    slices.push_back(std::make_unique<DrumSlice>(o));
  }
  // slices that cannot join a batch, or whose time step differs from the first batchable one's,
  // run alone afterwards
  std::vector<DrumSlice*> batched, alone;
  for (auto& s : slices) {
    const std::string why = s->whyNotBatchable();
    const bool sameStep =
        batched.empty() || s->system().timeStep() == batched.front()->system().timeStep();
    if (why.empty() && sameStep && s->rotating()) {
      batched.push_back(s.get());
    } else {
      alone.push_back(s.get());
      spdlog::info("batch: {} runs alone ({})", s->options().outputDirectory,
                   why.empty() ? (s->rotating() ? "a different time step" : "nothing left to run")
                               : why);
    }
  }
  if (!batched.empty())
    runBatched(batched);
  for (DrumSlice* s : alone) {
    const auto rotateStart = Clock::now();
    while (s->rotating()) {
      const std::int64_t n = s->stepsToNextSample();
      s->advanceAlone(n);
      s->afterSteps(n);
    }
    s->finish(secondsSince(rotateStart));
  }
  return 0;
}

} // namespace hikiln::dem

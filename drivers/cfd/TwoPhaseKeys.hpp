#pragma once
/// \file TwoPhaseKeys.hpp
/// \brief The case-file keys that the 2D continuum drum (`hikiln continuum`) and the 3D kiln
/// (`hikiln kiln`) share: material, gas, rheology (or a `hikiln calibrate` rheology file) and
/// numerics of the two-phase model.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <string>

namespace hikiln::cfd {

/// \brief Adds the shared keys (material.*, gas.*, rheology.*, numerics.*) to s.
void addTwoPhaseKeys(cases::CaseSchema& s);

/// \brief Reads the shared keys of a validated case into p (gravity and energy untouched); a
/// `rheology.file` (relative paths from the case file's folder) overrides m0, m1, the
/// strain-rate floor and mu_wall. Returns where the rheology came from: "case file" or the
/// rheology file's path.
std::string readTwoPhaseKeys(const cases::CaseFile& c, TwoPhaseParameters& p);

/// \brief Adds the energy equation's shared keys (heat.enabled, heat.alpha_eff, the heat
/// capacities, the gas conductivity) to s.
void addHeatKeys(cases::CaseSchema& s);

/// \brief Reads the keys of addHeatKeys into p (energy and thermal).
void readHeatKeys(const cases::CaseFile& c, TwoPhaseParameters& p);

} // namespace hikiln::cfd

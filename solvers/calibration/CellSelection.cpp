#include "solvers/calibration/CellSelection.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace hikiln::calibration {

namespace {
// Every member vector of CellSamples, so that copies and size checks cannot miss one.
std::array<std::vector<double>*, 8> fieldsOf(CellSamples& s) {
  return {&s.r,           &s.theta,      &s.volumeFraction, &s.pressure,
          &s.shearStress, &s.strainRate, &s.viscosity,      &s.frictionM};
}
std::array<const std::vector<double>*, 8> fieldsOf(const CellSamples& s) {
  return {&s.r,           &s.theta,      &s.volumeFraction, &s.pressure,
          &s.shearStress, &s.strainRate, &s.viscosity,      &s.frictionM};
}
} // namespace

void CellSamples::appendCell(const CellSamples& other, std::size_t i) {
  const auto to = fieldsOf(*this);
  const auto from = fieldsOf(other);
  for (std::size_t f = 0; f < to.size(); ++f)
    to[f]->push_back(from[f]->at(i));
}

void CellSamples::append(const CellSamples& other) {
  const auto to = fieldsOf(*this);
  const auto from = fieldsOf(other);
  for (std::size_t f = 0; f < to.size(); ++f)
    to[f]->insert(to[f]->end(), from[f]->begin(), from[f]->end());
}

CellSamples selectCells(const GridFields& fields, const SelectionOptions& options,
                        SelectionCounts* counts) {
  const std::size_t n = fields.valid.size();
  const auto columns = fieldsOf(fields.cells);
  for (const std::vector<double>* column : columns)
    if (column->size() != n)
      throw std::invalid_argument("cell selection: fields differ in length from 'valid'");
  SelectionCounts local;
  local.total = n;
  CellSamples selected;
  const CellSamples& c = fields.cells;
  for (std::size_t i = 0; i < n; ++i) {
    if (fields.valid[i] != 1) {
      ++local.invalid;
      continue;
    }
    bool finite = true;
    for (const std::vector<double>* column : columns)
      finite = finite && std::isfinite((*column)[i]);
    if (!finite) {
      ++local.nonFinite;
      continue;
    }
    if (!(c.strainRate[i] > options.minStrainRate)) {
      ++local.belowStrainRate;
      continue;
    }
    if (!(c.pressure[i] > 0.0)) {
      ++local.nonPositivePressure;
      continue;
    }
    selected.appendCell(c, i);
  }
  local.selected = selected.size();
  if (counts != nullptr)
    *counts = local;
  return selected;
}

} // namespace hikiln::calibration

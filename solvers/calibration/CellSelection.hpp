#pragma once
/// \file CellSelection.hpp
/// \brief Which averaged cells enter the calibration: valid, finite, sheared and compressed.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hikiln::calibration {

/// \brief Per-cell averaged values of one run (one entry per cell, all vectors equally long).
struct CellSamples {
  std::vector<double> r;              ///< distance from the drum centre [m]
  std::vector<double> theta;          ///< angle counter-clockwise from +x [rad]
  std::vector<double> volumeFraction; ///< [1]
  std::vector<double> pressure;       ///< p [Pa]
  std::vector<double> shearStress;    ///< q [Pa]
  std::vector<double> strainRate;     ///< gamma_dot [1/s]
  std::vector<double> viscosity;      ///< q / gamma_dot [Pa s]
  std::vector<double> frictionM;      ///< Drucker-Prager m = q / p [1]

  /// \brief Number of cells (the length of `pressure`).
  std::size_t size() const { return pressure.size(); }
  /// \brief Appends cell `i` of `other`.
  void appendCell(const CellSamples& other, std::size_t i);
  /// \brief Appends all cells of `other`.
  void append(const CellSamples& other);
};

/// \brief A whole grid as the averaged-field file stores it.
struct GridFields {
  CellSamples cells;               ///< every cell of the grid
  std::vector<std::uint8_t> valid; ///< 1 where enough material contributed
};

/// \brief Selection thresholds.
struct SelectionOptions {
  double minStrainRate =
      1e-2; ///< [1/s] cells at or below are not flowing (and q / gamma_dot blows up)
};

/// \brief Why cells were left out (each cell is counted under its first failing test, in order).
struct SelectionCounts {
  std::size_t total = 0;
  std::size_t invalid = 0;             ///< valid != 1
  std::size_t nonFinite = 0;           ///< a NaN or infinite value
  std::size_t belowStrainRate = 0;     ///< gamma_dot <= minStrainRate
  std::size_t nonPositivePressure = 0; ///< p <= 0
  std::size_t selected = 0;
};

/// \brief The cells with valid == 1, every value finite, strain rate above the floor and p > 0.
/// Throws std::invalid_argument when the vectors of `fields` differ in length.
CellSamples selectCells(const GridFields& fields, const SelectionOptions& options,
                        SelectionCounts* counts = nullptr);

} // namespace hikiln::calibration

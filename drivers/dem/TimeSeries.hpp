#pragma once
/// \file TimeSeries.hpp
/// \brief A CSV time series that is rewritten atomically on flush(), so it is always complete up to
/// the last flush, and that can be cut back to a restart time.

#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief Rows of numbers under named columns; the first column is the time.
class TimeSeries {
public:
  /// \brief A series stored at `path` with the given column names.
  TimeSeries(std::string path, std::vector<std::string> columns);
  /// \brief Reloads the rows already at `path` whose time is <= `time` (for a restart).
  void keepUntil(double time);
  /// \brief Appends a row (one value per column).
  void add(std::vector<double> row);
  /// \brief Writes the whole series to its path (write-then-rename).
  void flush() const;

private:
  std::string _path;
  std::vector<std::string> _columns;
  std::vector<std::vector<double>> _rows;
};

} // namespace hikiln::dem

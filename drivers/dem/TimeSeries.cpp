#include "drivers/dem/TimeSeries.hpp"

#include "drivers/io/AtomicFile.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hikiln::dem {

TimeSeries::TimeSeries(std::string path, std::vector<std::string> columns)
    : _path(std::move(path)), _columns(std::move(columns)) {}

void TimeSeries::keepUntil(double time) {
  _rows.clear();
  std::ifstream in(_path);
  std::string line;
  std::getline(in, line); // header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ','))
      row.push_back(std::stod(cell));
    if (row.size() == _columns.size() && row[0] <= time)
      _rows.push_back(row);
  }
}

void TimeSeries::add(std::vector<double> row) {
  if (row.size() != _columns.size()) {
    throw std::logic_error("TimeSeries::add: row has the wrong number of columns");
  }
  _rows.push_back(std::move(row));
}

void TimeSeries::flush() const {
  std::string text;
  for (std::size_t c = 0; c < _columns.size(); ++c)
    text += (c ? "," : "") + _columns[c];
  text += "\n";
  for (const auto& row : _rows) {
    for (std::size_t c = 0; c < row.size(); ++c)
      text += fmt::format("{}{:.9g}", c ? "," : "", row[c]);
    text += "\n";
  }
  io::writeTextAtomically(_path, text);
}

} // namespace hikiln::dem

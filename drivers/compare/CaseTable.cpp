#include "drivers/compare/CaseTable.hpp"

#include "drivers/compare/FieldComparison.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hikiln::compare {

namespace {

double valueAt(const nlohmann::json& j, const nlohmann::json::json_pointer& pointer) {
  if (!j.contains(pointer) || !j.at(pointer).is_number())
    return std::nan("");
  return j.at(pointer).get<double>();
}

// A quantity present for both runs: its JSON object's path and how the tables name it.
struct PairedColumn {
  std::string pointer, name, title;
};

std::vector<PairedColumn> pairedColumns() {
  std::vector<PairedColumn> columns;
  for (const std::string& field : spotFields())
    columns.push_back({"/spot/values/" + field, "spot_" + field, "spot " + field});
  columns.push_back({"/wall_slip_percent", "wall_slip_percent", "wall slip %"});
  columns.push_back({"/surface/angle_deg", "surface_angle_deg", "surface angle deg"});
  return columns;
}

// Map differences reported per case (relative L2 over the cells valid in both).
const std::vector<std::string>& mapColumns() {
  static const std::vector<std::string> names = {"pressure", "shear_stress", "velocity_x",
                                                 "velocity_y", "volume_fraction_normalised"};
  return names;
}

std::string label(const nlohmann::json& j) {
  return j.value("label", std::string("?"));
}

} // namespace

std::string casesCsv(const std::vector<nlohmann::json>& comparisons) {
  std::string csv = "case,diameter_m,rpm,fill";
  for (const PairedColumn& c : pairedColumns())
    csv += "," + c.name + "_dem," + c.name + "_continuum";
  csv += ",surface_rms_difference_m";
  for (const std::string& m : mapColumns())
    csv += ",relative_l2_" + m;
  csv += "\n";
  for (const nlohmann::json& j : comparisons) {
    csv +=
        fmt::format("{},{:.6g},{:.6g},{:.6g}", label(j), valueAt(j, "/drum/diameter"_json_pointer),
                    valueAt(j, "/drum/rpm"_json_pointer), valueAt(j, "/drum/fill"_json_pointer));
    for (const PairedColumn& c : pairedColumns())
      csv += fmt::format(",{:.6g},{:.6g}",
                         valueAt(j, nlohmann::json::json_pointer(c.pointer + "/dem")),
                         valueAt(j, nlohmann::json::json_pointer(c.pointer + "/continuum")));
    csv += fmt::format(",{:.6g}", valueAt(j, "/surface/rms_difference"_json_pointer));
    for (const std::string& m : mapColumns())
      csv += fmt::format(",{:.6g}",
                         valueAt(j, nlohmann::json::json_pointer("/maps/" + m + "/relative_l2")));
    csv += "\n";
  }
  return csv;
}

std::string casesMarkdown(const std::vector<nlohmann::json>& comparisons) {
  std::string header = "| case | D [m] | rpm | fill |", rule = "|---|---|---|---|";
  for (const PairedColumn& c : pairedColumns()) {
    header += " " + c.title + " (DEM / continuum) |";
    rule += "---|";
  }
  header += " surface rms diff [m] |";
  rule += "---|";
  for (const std::string& m : mapColumns()) {
    header += " rel. L2 " + m + " |";
    rule += "---|";
  }
  std::string md = header + "\n" + rule + "\n";
  for (const nlohmann::json& j : comparisons) {
    md += fmt::format("| {} | {:.3g} | {:.3g} | {:.3g} |", label(j),
                      valueAt(j, "/drum/diameter"_json_pointer),
                      valueAt(j, "/drum/rpm"_json_pointer), valueAt(j, "/drum/fill"_json_pointer));
    for (const PairedColumn& c : pairedColumns())
      md += fmt::format(" {:.3g} / {:.3g} |",
                        valueAt(j, nlohmann::json::json_pointer(c.pointer + "/dem")),
                        valueAt(j, nlohmann::json::json_pointer(c.pointer + "/continuum")));
    md += fmt::format(" {:.3g} |", valueAt(j, "/surface/rms_difference"_json_pointer));
    for (const std::string& m : mapColumns())
      md += fmt::format(" {:.3g} |",
                        valueAt(j, nlohmann::json::json_pointer("/maps/" + m + "/relative_l2")));
    md += "\n";
  }
  md += "\nSpot units: pressure and shear stress Pa, viscosity Pa s, strain rate 1/s, velocity_x "
        "m/s (comparison.json of each case says where the spot is and how each value is made).\n";
  return md;
}

} // namespace hikiln::compare

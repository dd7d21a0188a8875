#include "penumbra/photometry/distribution.h"

#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/photometry/analytic_distribution.h"
#include "penumbra/photometry/eulumdat.h"
#include "penumbra/photometry/ies.h"
#include "penumbra/photometry/table_distribution.h"

namespace penumbra::photometry {
namespace {

class Isotropic final : public Distribution {
 public:
  explicit Isotropic(double candela) : candela_(candela) {}
  double intensity(double, double) const override { return candela_; }
  double max_intensity() const override { return candela_; }
  double flux() const override { return 4 * pi * candela_; }
  Symmetry symmetry() const override { return Symmetry::isotropic; }

 private:
  double candela_;
};

// Reads one `lid` object, failing at JSON paths below it.
class SpecReader {
 public:
  SpecReader(const nlohmann::json& spec, const SpecContext& context)
      : spec_(spec), context_(context) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(context_.file,
                     key.empty() ? context_.json_path : context_.json_path + "." + key, message);
  }

  void allow_only(const std::string& form, std::initializer_list<const char*> keys) const {
    const std::set<std::string> allowed(keys.begin(), keys.end());
    for (const auto& item : spec_.items())
      if (!allowed.count(item.key())) {
        std::string list;
        for (const char* key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
        fail(item.key(), "unknown key for a " + form + " lid (allowed: " + list + ")");
      }
  }

  double number(const std::string& key) const {
    if (!spec_.contains(key)) fail("", "missing \"" + key + "\"");
    const auto& value = spec_.at(key);
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      fail(key, "must be a finite number");
    return value.get<double>();
  }
  double non_negative(const std::string& key) const {
    const double value = number(key);
    if (value < 0) fail(key, "must not be negative");
    return value;
  }

  std::vector<double> numbers(const std::string& key) const {
    if (!spec_.contains(key)) fail("", "missing \"" + key + "\"");
    const auto& value = spec_.at(key);
    if (!value.is_array()) fail(key, "must be an array of numbers");
    std::vector<double> result;
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (!value[i].is_number() || !std::isfinite(value[i].get<double>()))
        fail(key + "[" + std::to_string(i) + "]", "must be a finite number");
      result.push_back(value[i].get<double>());
    }
    return result;
  }

  double multiplier() const {
    if (!spec_.contains("multiplier")) return 1;
    const double value = number("multiplier");
    if (!(value > 0)) fail("multiplier", "must be positive");
    return value;
  }

  Interpolation interpolation() const {
    if (!spec_.contains("interpolation")) return Interpolation::linear;
    const auto& value = spec_.at("interpolation");
    if (value == "linear") return Interpolation::linear;
    if (value == "cosine") return Interpolation::cosine;
    fail("interpolation", "must be \"linear\" or \"cosine\", found " + value.dump());
  }

  std::filesystem::path file(const std::string& key) const {
    const auto& value = spec_.at(key);
    if (!value.is_string() || value.get<std::string>().empty()) fail(key, "must be a file name");
    const std::filesystem::path path = value.get<std::string>();
    return path.is_absolute() ? path : context_.base_dir / path;
  }

 private:
  const nlohmann::json& spec_;
  const SpecContext& context_;
};

std::shared_ptr<const Distribution> make_table(const SpecReader& in) {
  in.allow_only("table", {"table_deg", "candela", "interpolation", "multiplier"});
  const std::vector<double> angles = in.numbers("table_deg");
  std::vector<double> candela = in.numbers("candela");
  if (angles.size() < 2) in.fail("table_deg", "needs at least 2 angles");
  if (candela.size() != angles.size())
    in.fail("candela", "has " + std::to_string(candela.size()) + " values for " +
                           std::to_string(angles.size()) + " angles in table_deg");
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    if (angles[i] < 0 || angles[i] > 180) in.fail("table_deg" + at, "angles must lie in 0..180");
    if (i > 0 && !(angles[i - 1] < angles[i]))
      in.fail("table_deg" + at, "angles must strictly increase");
    if (candela[i] < 0) in.fail("candela" + at, "must not be negative");
  }
  const double multiplier = in.multiplier();
  for (double& value : candela) value *= multiplier;
  return make_axial_table(angles, candela, in.interpolation());
}

// runs a file reader, naming both the scene's JSON path and the file's own line.
template <typename Load>
std::shared_ptr<const Distribution> load_file(const SpecReader& in, const std::string& key,
                                              Load load) {
  try {
    return load();
  } catch (const InputError& e) {
    in.fail(key, e.what());
  }
}

}  // namespace

const char* symmetry_name(Symmetry symmetry) {
  switch (symmetry) {
    case Symmetry::isotropic:
      return "isotropic";
    case Symmetry::axial:
      return "axial";
    case Symmetry::quadrant:
      return "quadrant";
    case Symmetry::bilateral_c0_c180:
      return "bilateral-c0-c180";
    case Symmetry::bilateral_c90_c270:
      return "bilateral-c90-c270";
    case Symmetry::none:
      return "none";
  }
  return "none";
}

double Distribution::flux() const {
  // The midpoint rule in u = cos(gamma) and c: dOmega = du dc.
  constexpr int kU = 1800, kC = 720;
  double total = 0;
  for (int i = 0; i < kU; ++i) {
    const double gamma = std::acos(1 - (i + 0.5) * (2.0 / kU));
    for (int j = 0; j < kC; ++j) total += intensity(gamma, (j + 0.5) * (2 * pi / kC));
  }
  return total * (2.0 / kU) * (2 * pi / kC);
}

std::shared_ptr<const Distribution> make_isotropic(double candela) {
  return std::make_shared<Isotropic>(candela);
}

std::shared_ptr<const Distribution> make_distribution(const nlohmann::json& spec,
                                                      const SpecContext& context) {
  const SpecReader in(spec, context);
  if (!spec.is_object()) in.fail("", "a lid must be a JSON object");
  std::string form;
  for (const char* key : {"table_deg", "cos_power", "cardioid", "ies", "ldt"}) {
    if (!spec.contains(key)) continue;
    if (!form.empty())
      in.fail(key, "a lid has one form, found both \"" + form + "\" and \"" + key + "\"");
    form = key;
  }
  if (form.empty()) {
    if (!spec.contains("candela"))
      in.fail("",
              "a lid needs one of \"table_deg\", \"cos_power\", \"cardioid\", \"ies\", \"ldt\" "
              "or \"candela\" alone");
    in.allow_only("isotropic", {"candela", "multiplier"});
    return make_isotropic(in.non_negative("candela") * in.multiplier());
  }
  if (form == "table_deg") return make_table(in);
  if (form == "cos_power") {
    in.allow_only("cos_power", {"cos_power", "spread_deg", "candela", "multiplier"});
    const double power = in.non_negative("cos_power");
    const double spread = spec.contains("spread_deg") ? in.number("spread_deg") : 90.0;
    if (!(spread > 0 && spread <= 90))
      in.fail("spread_deg",
              "must lie in (0, 90]: beyond 90 degrees cos^k is negative or a back lobe");
    return std::make_shared<CosPowerDistribution>(in.non_negative("candela") * in.multiplier(),
                                                  power, spread);
  }
  if (form == "cardioid") {
    in.allow_only("cardioid", {"cardioid", "candela", "multiplier"});
    if (spec.at("cardioid") != true) in.fail("cardioid", "must be true");
    return std::make_shared<CardioidDistribution>(in.non_negative("candela") * in.multiplier());
  }
  if (form == "ies") {
    in.allow_only("ies", {"ies", "interpolation", "multiplier"});
    const auto path = in.file("ies");
    const Interpolation interpolation = in.interpolation();
    const double multiplier = in.multiplier();
    return load_file(in, "ies", [&] { return load_ies(path, interpolation, multiplier); });
  }
  in.allow_only("ldt", {"ldt", "lamp_set", "interpolation", "multiplier"});
  const auto path = in.file("ldt");
  std::size_t lamp_set = 0;
  if (spec.contains("lamp_set")) {
    const auto& value = spec.at("lamp_set");
    if (!value.is_number_integer() || value.get<long>() < 0)
      in.fail("lamp_set", "must be a lamp set index (0 for the first)");
    lamp_set = value.get<std::size_t>();
  }
  const Interpolation interpolation = in.interpolation();
  const double multiplier = in.multiplier();
  return load_file(in, "ldt",
                   [&] { return load_eulumdat(path, interpolation, lamp_set, multiplier); });
}

}  // namespace penumbra::photometry

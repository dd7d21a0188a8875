#include "penumbra/photometry/distribution.h"

#include <nlohmann/json.hpp>

#include "penumbra/input_error.h"

namespace penumbra::photometry {
namespace {

class Isotropic final : public Distribution {
 public:
  explicit Isotropic(double candela) : candela_(candela) {}
  double intensity(double, double) const override { return candela_; }
  double max_intensity() const override { return candela_; }

 private:
  double candela_;
};

}  // namespace

std::shared_ptr<const Distribution> make_isotropic(double candela) {
  return std::make_shared<Isotropic>(candela);
}

std::shared_ptr<const Distribution> make_distribution(const nlohmann::json& spec,
                                                      const SpecContext& context) {
  // TODO(photometry issue): tables, cos_power, IES, EULUMDAT.
  if (spec.is_object() && spec.contains("candela") && spec.size() == 1 &&
      spec["candela"].is_number())
    return make_isotropic(spec["candela"].get<double>());
  throw InputError(context.file, context.json_path, "this distribution form is not built yet");
}

}  // namespace penumbra::photometry

#pragma once
// The EMPS fluid of a scene against its polygon walls (static or with prescribed motion).
#include "fluid_emps/emps_fluid.hpp"
#include "fsi_app/model.hpp"
#include "geometry_erp/wall_set.hpp"

#include <memory>

namespace fsi::app {

class FluidModel final : public Model {
public:
  /// Builds walls, fills the regions with particles and maps the options. Throws InputError
  /// (scene file and line) for a motion table or region that does not fit.
  explicit FluidModel(const Scene& scene);
  void advance(double time, double dt) override;
  std::optional<double> stable_dt(double courant) const override;
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  void report(JsonObject& run) const override;

private:
  std::unique_ptr<erp::WallSet> walls_;
  std::unique_ptr<emps::EmpsFluid> fluid_;
  std::size_t initial_count_ = 0;
  mutable std::vector<double> xy_, v_, flag_; // output buffers
};

} // namespace fsi::app

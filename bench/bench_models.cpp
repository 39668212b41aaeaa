// make bench: the models it times (bench_models.hpp).  The bar and the strip
// are those of the reference figures of issue 22.
#include "bench_models.hpp"

#include <chrono>

#include "fe/solver.hpp"
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend;

// The materials and models: bench_models.hpp says what each is.
namespace {
/// A model run point by point: every call forwarded to `m`, but no lane twin bound (Material::bind_lanes
/// not overridden), so that the element kernel takes its scalar path: the cost before the model's lanes.
class ScalarPath final : public material::Material {
 public:
  explicit ScalarPath(std::shared_ptr<const material::Material> m) : m_(std::move(m)) {}
  int state_size() const override { return m_->state_size(); }
  using Material::init_state;
  void init_state(double* s, const material::SheetAxes& a) const override { m_->init_state(s, a); }
  using Material::update;
  void update(const double d[6], const material::Spin& w, double s[6], double* st) const override {
    m_->update(d, w, s, st);
  }
  double density() const override { return m_->density(); }
  double youngs_modulus() const override { return m_->youngs_modulus(); }
  double poisson_ratio() const override { return m_->poisson_ratio(); }
  double tangent_ratio(const double* s, const double* st) const override { return m_->tangent_ratio(s, st); }
  bool uses_spin() const override { return m_->uses_spin(); }
  bool directional() const override { return m_->directional(); }
  double plastic_strain(const double* st) const override { return m_->plastic_strain(st); }
  bool has_back_stress() const override { return m_->has_back_stress(); }
  void back_stress(const double* st, double a[6]) const override { m_->back_stress(st, a); }
  bool sheet_axes(const double* st, double rd[3], double nd[3]) const override { return m_->sheet_axes(st, rd, nd); }
  std::string describe() const override { return m_->describe() + " (scalar path)"; }

 private:
  std::shared_ptr<const material::Material> m_;
};
}  // namespace

material::Yld2004 bench_yld2004_set() {
  material::Yld2004 yld;
  yld.a = 8;
  yld.c1 = {1.0059518, 1.1865517, 0.0087202487, 0.75613553, 1.1445682, 0.84840891, 1, 1, 0.17885443};
  yld.c2 = {0.87834346, 1.1811921, 1.0479014, 1.2886127, 0.036486783, 1.5701502, 1, 1, 1.5886608};
  return yld;
}

std::shared_ptr<const material::Material> bar_material(const std::string& name) {
  const double E = 70000.0, nu = 0.33, rho = 2.7e-9;
  const material::HardeningCurve curve({0.0, 1.0}, {100.0, 600.0});
  const material::Hill48 hill = material::Hill48::from_r_values(0.65, 0.65, 0.72);
  material::KinematicHardening split, chab, none;
  split.beta = 0.3;
  chab.chaboche = {{5000.0, 40.0}};
  if (name == "j2") return std::make_shared<material::J2Isotropic>(E, nu, rho, curve);
  if (name == "split") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, split);
  if (name == "chaboche") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, chab);
  if (name == "hill48") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, none, hill);
  if (name == "hill48_chaboche") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, chab, hill);
  if (name == "yld2004") return std::make_shared<material::Yld2004Plasticity>(E, nu, rho, curve, none, bench_yld2004_set());
  const std::string scalar = "_scalar";  // e.g. hill48_scalar: the same model on the kernel's scalar path
  if (name.size() > scalar.size() && name.ends_with(scalar)) {
    auto m = bar_material(name.substr(0, name.size() - scalar.size()));
    return m ? std::make_shared<ScalarPath>(std::move(m)) : nullptr;
  }
  return nullptr;
}

fe::Model bar(int nx, int ny, int nz, std::shared_ptr<const material::Material> mat) {
  fe::Model m;
  const double h = 1.0;  // 1 mm elements
  m.mesh = fe::structured_block(fe::uniform_lines(0, nx * h, nx), fe::uniform_lines(0, ny * h, ny),
                                fe::uniform_lines(0, nz * h, nz));
  m.material = mat ? std::move(mat) : bar_material("j2");
  fe::Step s;
  s.duration = 1.0;  // long; runs are cut by cycle count
  s.fixed = {{"xmin", {true, true, true}}, {"xmax", {false, true, true}}};
  s.velocities.push_back({"xmax", {1, 0, 0}, fe::History::constant(20000.0)});
  m.steps.push_back(s);
  return m;
}

fe::Model strip_on_pin() {
  fe::Model m;
  // 1.04 mm thick, 12.7 mm half-width strip over a 12.7 mm pin: 100 x 8 x 4 = 3,200 elements in the
  // refined zone plus 2 x 25 x 8 x 4 coarse = 4,800 in all.
  m.mesh = fe::structured_block(fe::piecewise_lines({-40, -12.5, 12.5, 40}, {25, 100, 25}), fe::uniform_lines(0, 12.7, 8),
                                fe::uniform_lines(0, 1.04, 4));
  m.material = std::make_shared<material::J2Isotropic>(70000.0, 0.33, 2.7e-9,
                                                       material::HardeningCurve({0.0, 1.0}, {100.0, 600.0}));
  contact::Surface c;
  c.kind = contact::Surface::Kind::cylinder;
  c.origin = {0, 0, -6.35};
  c.axis = {0, 1, 0};
  c.R = 6.35;
  m.add_rigid_contact("pin", c, "zmin", std::make_shared<friction::Coulomb>(0.1));
  fe::Step s;
  s.duration = 1.0;
  s.fixed = {{"ymin", {false, true, false}}};
  s.forces.push_back({"xmin", {-1, 0, 0}, fe::History::constant(750.0)});
  s.velocities.push_back({"xmax", {1, 0, 0}, fe::History::constant(50.0)});
  m.steps.push_back(s);
  m.mass_scaling = 100;
  return m;
}

namespace {
struct Done {};  // the cycle budget is spent (not a std::exception: a solver fault must not pass for it)
}  // namespace

double seconds(fe::Model m, long cycles, fe::PhaseTimes* phases, double* forked_share) {
  fe::Solver s(m);
  s.time_phases(phases);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    s.run_step(0, [&](const fe::Progress& p) {
      if (p.cycle >= cycles) throw Done{};
    });
  } catch (const Done&) {
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (forked_share) *forked_share = s.cycles() > 0 ? static_cast<double>(s.forked_cycles()) / s.cycles() : 0;
  return wall;
}

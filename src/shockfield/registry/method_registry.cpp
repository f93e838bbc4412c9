#include "shockfield/registry/method_registry.hpp"

#include <vector>

#include "shockfield/dbm/run_case.hpp"
#include "shockfield/granular/run_case.hpp"
#include "shockfield/macroparticle/run_case.hpp"
#include "shockfield/md/run_case.hpp"
#include "shockfield/mpm/run_case.hpp"
#include "shockfield/pd/run_case.hpp"
#include "shockfield/phasefield/run_case.hpp"

namespace shockfield {

const std::map<std::string, MethodFactory>& method_registry() {
  static const std::map<std::string, MethodFactory> table{
      {"dbm", &dbm::make_method}, {"md", &md::make_method}, {"mpm", &mpm::make_method}, {"pd", &pd::make_method},
      {"granular", &granular::make_method}, {"macroparticle", &macroparticle::make_method},
      {"phasefield", &phasefield::make_method}};
  return table;
}

const MethodFactory& method_factory(const Config& root) {
  std::vector<std::string> names;
  for (const auto& [name, factory] : method_registry()) names.push_back(name);
  return method_registry().at(root.get_choice("method", names));
}

}  // namespace shockfield

#pragma once
// The keys of every registered bond model, for tests parameterised over all of them.
#include <string>
#include <vector>

#include "bonds/bond_model.hpp"

namespace bpm::test {

inline std::vector<std::string> model_keys() {
  std::vector<std::string> keys;
  for (const BondModelInfo& info : bond_models()) keys.emplace_back(info.key);
  return keys;
}

}  // namespace bpm::test

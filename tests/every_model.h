// Suites parameterised by the model registry, so that a model added to it is tested by every
// such suite without a list to extend:
//   INSTANTIATE_TEST_SUITE_P(EveryModel, Suite, every_model(), model_test_name);
#pragma once

#include <brdfnav/core/models.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace brdfnav {

inline auto every_model() {
  return ::testing::ValuesIn(models().begin(), models().end());
}

inline std::string model_test_name(const ::testing::TestParamInfo<ModelInfo>& info) {
  return std::string(info.param.name);
}

// How GoogleTest prints the parameter (instead of the struct's bytes).
inline void PrintTo(const ModelInfo& model, std::ostream* os) {
  *os << model.name;
}

}  // namespace brdfnav

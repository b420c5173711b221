#include <verification/matrix/quantity_status.hpp>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>

namespace beamimpact::verification {

const std::vector<QuantityStatus>& quantity_statuses() {
  static const std::vector<QuantityStatus> all = {
      QuantityStatus::kPass,         QuantityStatus::kFail,
      QuantityStatus::kNotConverged, QuantityStatus::kReferenceUncertain,
      QuantityStatus::kFailed,       QuantityStatus::kSkipped,
      QuantityStatus::kNotApplicable};
  return all;
}

const char* to_string(QuantityStatus s) {
  switch (s) {
    case QuantityStatus::kPass: return "pass";
    case QuantityStatus::kFail: return "fail";
    case QuantityStatus::kNotConverged: return "not converged";
    case QuantityStatus::kReferenceUncertain: return "reference uncertain";
    case QuantityStatus::kFailed: return "failed";
    case QuantityStatus::kSkipped: return "skipped";
    case QuantityStatus::kNotApplicable: return "not applicable";
  }
  return "?";
}

QuantityStatus parse_quantity_status(std::string_view text, const std::string& file, const std::string& key) {
  std::string words;
  for (QuantityStatus s : quantity_statuses()) {
    if (text == to_string(s)) return s;
    words += fmt::format("{}'{}'", words.empty() ? "" : ", ", to_string(s));
  }
  throw InputError(file, key, fmt::format("expected a quantity status ({}), got '{}'", words, text));
}

const char* describe(QuantityStatus s) {
  switch (s) {
    case QuantityStatus::kFail: return "fail (outside tolerance)";
    case QuantityStatus::kFailed: return "run failed";
    default: return to_string(s);
  }
}

bool passes(QuantityStatus s) { return s == QuantityStatus::kPass || s == QuantityStatus::kNotApplicable; }

}  // namespace beamimpact::verification

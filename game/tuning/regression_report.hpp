// Machine-readable reports of a regression run, for CI systems and scripts:
// JUnit XML (one <testcase> per check; a failure carries expected, actual and tolerance)
// and a JSON document (DESIGN §6 names). The table for people is regression_table().
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/tuning/regression.hpp"

namespace sweetspot {

/// JUnit XML as Jenkins, GitLab and GitHub's test reporters read it: <testsuites> with one
/// <testsuite> per case file and one <testcase> per checked quantity. Text that is not
/// valid in XML 1.0 (control bytes, bytes that are not UTF-8) is replaced by U+FFFD.
std::string regression_junit(const std::vector<RegressionCaseResult>& results);

/// {"cases": [{"name", "path", "reference", "passed", "checks": [{"quantity", "pass",
/// "expected", "got", "delta", "tolerance", "unit" (as the case wrote them),
/// "expected_si", "got_si", "tolerance_si", "si_unit", "origin"}]}], "checks", "failed"}.
/// Text checks (contact) have no *_si fields.
nlohmann::json regression_json(const std::vector<RegressionCaseResult>& results);

}  // namespace sweetspot

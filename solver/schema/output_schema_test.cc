#include <solver/schema/output_schema.hpp>

#include <algorithm>

#include <gtest/gtest.h>

namespace beamimpact {
namespace {

// The contract of docs/scene-format.md: t, then 12 columns per contact (suffix _k from the second
// contact on), then 6 model columns. Written out here by hand, not derived from the code.
TEST(OutputSchema, ColumnsFollowInterfaceMd) {
  const std::vector<std::string> one = {
      "t",    "R",    "tau",   "gap",     "ua_x",   "ua_y",       "va_x",      "va_y", "ub_x", "ub_y",
      "vb_x", "vb_y", "state", "kinetic", "strain", "dissipated", "load_work", "px",   "py"};
  EXPECT_EQ(history_columns(1), one);
  const auto two = history_columns(2);
  EXPECT_EQ(two.size(), 1u + 2u * 12u + 6u);
  EXPECT_EQ(two[13], "R_2");
  EXPECT_EQ(two[24], "state_2");
  EXPECT_EQ(contact_column("vb_y", 3), "vb_y_3");
  EXPECT_EQ(contact_column("R", 1), "R");
}

TEST(OutputSchema, EnumFormsAreTheDocumentedStrings) {
  EXPECT_STREQ(to_string(ContactKind::kEndToEnd), "end_to_end");
  EXPECT_STREQ(to_string(ContactKind::kNodeToNode), "node_to_node");
  EXPECT_STREQ(to_string(ContactKind::kNodeToSurface), "node_to_surface");
  EXPECT_EQ(static_cast<int>(ContactState::kSlip), 2);  // the integer in column `state`
  const auto j = schema_json();
  EXPECT_EQ(j.at("state_values").at("3"), "closed");
  EXPECT_EQ(j.at("contact_columns").size(), 12u);
}

}  // namespace
}  // namespace beamimpact

// The table model's two renderings on hand-made tables whose text follows from the formats
// (GitHub Markdown pipe tables; RFC 4180 CSV).
#include <verification/jobs/Table.hpp>

#include <stdexcept>

#include <gtest/gtest.h>

namespace beamimpact::jobs {
namespace {

TEST(Table, MarkdownEscapesPipes) {
  Table t({"norm", "limit"});
  t.add({"impulse", "|Q_R - ref| <= 1.25 E_R"}).add({"", "<= 0.01"});
  EXPECT_EQ(t.markdown(),
            "| norm | limit |\n|---|---|\n| impulse | \\|Q_R - ref\\| <= 1.25 E_R |\n|  | <= 0.01 |\n");
}

TEST(Table, CsvQuotesOnlyWhatNeedsItOrQuotedColumns) {
  Table t({"dt", "message"});
  t.add({"0.01", "a, \"b\"\nc"}).add({"0.02", ""});
  EXPECT_EQ(t.csv(), "dt,message\n0.01,\"a, \"\"b\"\" c\"\n0.02,\n");
  t.quote_column(1);
  EXPECT_EQ(t.csv(), "dt,message\n0.01,\"a, \"\"b\"\" c\"\n0.02,\"\"\n");
}

TEST(Table, RowOfTheWrongWidthIsRefused) {
  Table t({"a", "b"});
  EXPECT_THROW(t.add({"1"}), std::logic_error);
  EXPECT_EQ(t.rows(), 0u);
}

}  // namespace
}  // namespace beamimpact::jobs

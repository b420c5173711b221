// The pages of `score` and `conform` (page.hpp): made by reports/render.py from the JSON; a
// missing interpreter, render.py or Jinja2, or a renderer that fails, is one line that says the
// page was not made and the command that makes it, and no page older than the JSON is left.
#include <fstream>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>

#include <tools/beamimpact/page.hpp>

namespace beamimpact::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kPython = "/usr/bin/python3";  // Debian's, with python3-jinja2 (tools/install-deps.sh)

std::string slurp(const fs::path& f) {
  std::ifstream in(f);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A scorecard folder holding the hand-made fixture (reports/testdata/scorecard) and a stale page.
fs::path scorecard_dir(const std::string& name) {
  const fs::path dir = temp_path(name);
  fs::create_directories(dir);
  fs::copy_file(source_dir() / "reports/testdata/scorecard/scorecard.json", dir / "scorecard.json");
  std::ofstream(dir / "scorecard.html") << "a page of an earlier run";
  return dir;
}

void expect_not_made(const PageOutcome& o, const fs::path& dir, const std::string& why) {
  EXPECT_FALSE(o.made) << o.line;
  EXPECT_NE(o.line.find("page: not made (" + why), std::string::npos) << o.line;
  EXPECT_NE(o.line.find("make it with: python3 "), std::string::npos) << o.line;
  EXPECT_NE(o.line.find("reports/render.py scorecard " + dir.string()), std::string::npos) << o.line;
  EXPECT_FALSE(fs::exists(dir / "scorecard.html")) << "a stale page is left beside the JSON";
}

TEST(Page, MadeFromTheJsonByRenderPy) {
  const fs::path dir = scorecard_dir("made");
  const PageOutcome o = render_page("scorecard", dir, kPython, source_dir());
  EXPECT_TRUE(o.made) << o.line;
  EXPECT_EQ(o.line, "page: " + (dir / "scorecard.html").string());
  // The fixture's verdict line, on the page (the page's content: reports/render_test.py).
  EXPECT_NE(slurp(dir / "scorecard.html").find("score demo: FAILED: 1 of 3 quantities failed (fixture)"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "scorecard.render.log"));
}

TEST(Page, NoPythonSaysSoAndHowToMakeThePage) {
  const fs::path dir = scorecard_dir("no-python");
  expect_not_made(render_page("scorecard", dir, "", source_dir()), dir, "python3 is not on PATH");
  expect_not_made(render_page("scorecard", dir, dir / "python3", source_dir()), dir,
                  (dir / "python3").string());
}

TEST(Page, NoRendererSaysSoAndHowToMakeThePage) {
  const fs::path dir = scorecard_dir("no-renderer");
  const fs::path empty = temp_path("empty-root");
  fs::create_directories(empty);
  expect_not_made(render_page("scorecard", dir, kPython, empty), dir, (empty / "reports/render.py").string());
  expect_not_made(render_page("scorecard", dir, kPython, ""), dir, "no data root");
}

TEST(Page, NoJinja2SaysSoAndHowToMakeThePage) {
  // A jinja2 module that cannot be imported, first on the path: Python as on a machine without
  // python3-jinja2.
  const fs::path dir = scorecard_dir("no-jinja2");
  const fs::path fake = temp_path("fake-site");
  fs::create_directories(fake);
  std::ofstream(fake / "jinja2.py") << "raise ImportError('no module named jinja2')\n";
  const char* old = std::getenv("PYTHONPATH");
  const std::string kept = old ? old : "";
  setenv("PYTHONPATH", fake.c_str(), 1);
  const PageOutcome o = render_page("scorecard", dir, kPython, source_dir());
  old ? setenv("PYTHONPATH", kept.c_str(), 1) : unsetenv("PYTHONPATH");
  expect_not_made(o, dir, "Jinja2 is missing");
}

TEST(Page, AFailingRendererIsOneLineWithItsReason) {
  const fs::path dir = scorecard_dir("bad-json");
  std::ofstream(dir / "scorecard.json") << R"({"scenes": []})";  // no method, command, version
  const PageOutcome o = render_page("scorecard", dir, kPython, source_dir());
  expect_not_made(o, dir, "render.py exited 2: render: scorecard.json: key 'method' missing");
  EXPECT_EQ(o.line.find('\n'), std::string::npos) << o.line;
}

}  // namespace
}  // namespace beamimpact::testing

// The 3D page's data (export/part_page.h): what the script reads is the program, its moves, its
// findings and its constructions, and nothing from the input can end the data's script element.
// The page in a browser is tests/browser/pages.mjs's.
#include "kerf/export/part_page.h"

#include "kerf/converter/pipeline.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using kerf::converter::Pipeline;
using kerf::converter::PipelineOptions;
using kerf::converter::runPipeline;
using kerf::exporter::partPage;
using kerf::exporter::PartPageOptions;

/// The JSON text of the page's data element, with the script escapes undone by the JSON parser.
nlohmann::json pageData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"kerf-data\">";
  const std::size_t from = html.find(open);
  const std::size_t to = html.find("</script>", from);
  EXPECT_NE(from, std::string::npos);
  EXPECT_NE(to, std::string::npos);
  return nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
}

Pipeline pipelineOf(const std::string& name, const std::string& text) {
  PipelineOptions options;
  options.centreWords = true;
  return runPipeline({name, text}, options);
}

TEST(part_page_test, the_data_is_the_program) {
  const Pipeline p = pipelineOf("sector.nc", "G92 X-5. Y0\nG01 X0 Y0\nX40. Y0\nG03 X0 Y40. R40.\nG01 X0 Y0\nM02\n");
  const auto page = partPage(p, "sector.nc", p.diags.all(), PartPageOptions{});
  const nlohmann::json data = pageData(page.html);
  EXPECT_EQ(data["program"]["lines"].size(), 6u);
  EXPECT_EQ(data["program"]["lines"][3], "G03 X0 Y40. R40.");
  EXPECT_EQ(data["name"], "sector.nc");
  EXPECT_GT(page.triangles, 0u);
  EXPECT_FALSE(page.coarse);
  EXPECT_FALSE(page.truncated);
  // A construction for each block with a move, the arc's with both candidate centres.
  EXPECT_EQ(page.constructions, 4u);
  bool arc = false;
  for (const auto& c : data["constructions"]["blocks"])
    if (c["line"] == 4) {
      arc = true;
      const auto& roles = c["roles"];
      EXPECT_NE(std::find(roles.begin(), roles.end(), "centre"), roles.end());
      EXPECT_NE(std::find(roles.begin(), roles.end(), "rejected"), roles.end());
    }
  EXPECT_TRUE(arc);
  // The scripts are embedded and allowed by their hashes, nothing else.
  EXPECT_NE(page.html.find("script-src 'sha256-"), std::string::npos);
  EXPECT_EQ(page.html.find("<script src="), std::string::npos);
}

TEST(part_page_test, input_stays_data) {
  const std::string hostile = "G01 X10. Y0 (</script><script>alert(1)</script><!-- \xe2\x80\xa8)";
  const Pipeline p = pipelineOf("a<b>.nc", "G92 X0 Y0\n" + hostile + "\nX10. Y10.\nX0 Y0\nM02\n");
  const auto page = partPage(p, "a<b>.nc", p.diags.all(), PartPageOptions{});
  // The one element the input reaches is the data, and it ends where the page ends it.
  EXPECT_EQ(page.html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(page.html.find("<!-- "), std::string::npos);
  EXPECT_NE(page.html.find("<title>a&lt;b&gt;.nc"), std::string::npos);
  const nlohmann::json data = pageData(page.html);
  EXPECT_EQ(data["program"]["lines"][1], hostile);
}

// Over the budget the part is sent coarse (the exact mesh stops at the budget), and the page says so.
TEST(part_page_test, a_part_over_the_budget_is_sent_coarse) {
  const Pipeline p = pipelineOf("sector.nc", "G92 X0 Y0\nG01 X40. Y0\nG03 X0 Y40. R40.\nG01 X0 Y0\nM02\n");
  PartPageOptions options;
  const auto exact = partPage(p, "sector.nc", p.diags.all(), options);
  ASSERT_GT(exact.triangles, 8u);
  options.triangleBudget = 8;
  const auto page = partPage(p, "sector.nc", p.diags.all(), options);
  EXPECT_TRUE(page.coarse);
  EXPECT_FALSE(page.truncated);
  EXPECT_LT(page.triangles, exact.triangles);
  EXPECT_NE(pageData(page.html)["scene"]["size"].get<std::string>().find("drawn coarse"), std::string::npos);
}

TEST(part_page_test, a_report_page_loads_its_scripts_from_the_folder) {
  const Pipeline p = pipelineOf("line.nc", "G92 X0 Y0\nG01 X10. Y0\nM02\n");
  PartPageOptions options;
  options.scriptFiles = true;
  const auto page = partPage(p, "line.nc", p.diags.all(), options);
  for (const kerf::exporter::PageScript& script : kerf::exporter::partPageScripts()) {
    EXPECT_NE(page.html.find("<script src=\"" + std::string(script.file) + "\">"), std::string::npos) << script.file;
    EXPECT_FALSE(script.text.empty());
  }
  EXPECT_NE(page.html.find("script-src 'self'"), std::string::npos);
}

}  // namespace

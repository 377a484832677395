// The integrator table is the one source of the schemes' names and orders:
// the factory, the docs' tables and the launch file's argument doc follow it.
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {
namespace {

std::string ReadSource(const std::string& relative_path) {
  std::ifstream file(std::string(RBS_SOURCE_DIR) + "/" + relative_path);
  EXPECT_TRUE(file.good()) << relative_path;
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

TEST(IntegratorTable, FactoryNamesAndOrdersComeFromTheTable) {
  ASSERT_FALSE(IntegratorTable().empty());
  EXPECT_STREQ(IntegratorTable().front().name, kDefaultIntegrator);
  ASSERT_EQ(IntegratorNames().size(), IntegratorTable().size());
  std::set<std::string> unique;
  for (std::size_t i = 0; i < IntegratorTable().size(); ++i) {
    const IntegratorInfo& info = IntegratorTable()[i];
    EXPECT_EQ(IntegratorNames()[i], info.name);
    EXPECT_TRUE(unique.insert(info.name).second) << info.name;
    EXPECT_NE(std::string(info.summary), "");
    const auto integrator = MakeIntegrator(info.name);
    EXPECT_STREQ(integrator->name(), info.name);
    EXPECT_EQ(integrator->order(), info.order);
    EXPECT_EQ(FindIntegrator(info.name), &info);
  }
  EXPECT_EQ(FindIntegrator("verlet"), nullptr);
}

// Every markdown table row "| `name` | order |" of a document, as name → order.
std::map<std::string, int> DocumentedOrders(const std::string& text) {
  std::map<std::string, int> orders;
  const std::regex row(R"(\n\|\s*`([a-z_0-9]+)`[^|]*\|\s*(\d+)\s*\|)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), row); it != std::sregex_iterator(); ++it) {
    orders[(*it)[1]] = std::stoi((*it)[2]);
  }
  return orders;
}

TEST(IntegratorTable, TheDocsTablesListEverySchemeWithItsOrder) {
  std::map<std::string, int> expected;
  for (const IntegratorInfo& info : IntegratorTable()) expected[info.name] = info.order;
  for (const char* document : {"README.md", "doc/physics.md"}) {
    EXPECT_EQ(DocumentedOrders(ReadSource(document)), expected) << document;
  }
}

TEST(IntegratorTable, TheLaunchFileNamesEveryScheme) {
  const std::string launch = ReadSource("launch/rigid_body_sim.launch");
  std::smatch doc;
  ASSERT_TRUE(std::regex_search(launch, doc, std::regex(R"re(<arg name="integrator"[^>]*doc="([^"]*)")re")))
      << "no doc for the integrator arg";
  for (const std::string& name : IntegratorNames()) {
    EXPECT_TRUE(std::regex_search(doc[1].str(), std::regex("\\b" + name + "\\b"))) << name;
  }
}

}  // namespace
}  // namespace rigid_body_sim::core

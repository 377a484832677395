// The integrator table is the one source of the schemes' names and orders:
// the factory, the docs' tables and the launch file's argument doc follow it.
#include <cctype>
#include <fstream>
#include <map>
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

// Every markdown table row "| `name` | order | ..." of a document, as name → order.
std::map<std::string, int> DocumentedOrders(const std::string& text) {
  std::map<std::string, int> orders;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::size_t name_end = line.find('`', 3);
    const std::size_t cell = line.find('|', name_end);
    if (name_end == std::string::npos || cell == std::string::npos) continue;
    std::size_t digit = line.find_first_not_of(' ', cell + 1);
    if (digit == std::string::npos || !std::isdigit(static_cast<unsigned char>(line[digit])))
      continue;
    orders[line.substr(3, name_end - 3)] = std::stoi(line.substr(digit));
  }
  return orders;
}

// Whether `word` stands in `text` with no letter, digit or '_' on either side.
bool ContainsWord(const std::string& text, const std::string& word) {
  const auto is_word = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool left = at == 0 || !is_word(text[at - 1]);
    const std::size_t end = at + word.size();
    if (left && (end == text.size() || !is_word(text[end]))) return true;
  }
  return false;
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
  const std::size_t arg = launch.find("<arg name=\"integrator\"");
  ASSERT_NE(arg, std::string::npos) << "no integrator arg";
  const std::size_t doc_start = launch.find("doc=\"", arg);
  ASSERT_NE(doc_start, std::string::npos) << "no doc for the integrator arg";
  const std::size_t doc_end = launch.find('"', doc_start + 5);
  const std::string doc = launch.substr(doc_start + 5, doc_end - doc_start - 5);
  for (const std::string& name : IntegratorNames()) EXPECT_TRUE(ContainsWord(doc, name)) << name;
}

}  // namespace
}  // namespace rigid_body_sim::core

// docs/CLI.md against the executable's own help: every verb that `gridifs --help` lists must be
// named there as `gridifs VERB`, and every long option that `gridifs VERB --help` lists must appear
// there as `--name`. A verb added or renamed, or an option added or renamed, without its
// documentation fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using namespace test_support;

const std::filesystem::path kCliDoc = std::filesystem::path(GRIDIFS_SOURCE_DIR) / "docs" / "CLI.md";

/// Whether `c` may continue a verb or option name, so that "--part" is not found inside "--parts".
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_'; }

/// Whether `text` holds `word` where no further name character follows it.
bool mentions(const std::string& text, const std::string& word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    if (end == text.size() || !isNameChar(text[end])) return true;
  }
  return false;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

template <class Names>
std::string joined(const Names& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

/// The verbs of `gridifs --help`. It is not CLI11's help but app/cli.cpp's printUsage: under
/// "Usage:", one line "  gridifs VERB   SYNOPSIS: summary" per registered verb, after the
/// modeller's own line "  gridifs [FILE]   open the modeller ...", which is skipped.
std::vector<std::string> verbsOf(const std::string& help) {
  const std::string prefix = "  gridifs ";
  std::vector<std::string> verbs;
  for (const std::string& line : linesOf(help)) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream words(line.substr(prefix.size()));
    std::string verb;
    words >> verb;
    if (verb.empty() || verb[0] == '[' || verb[0] == '-') continue;
    verbs.push_back(verb);
  }
  return verbs;
}

/// The long options of a CLI11 help page (`gridifs VERB --help`, CLI11's Formatter): each option
/// is a line that starts with two spaces and its comma-separated names, then its type and
/// description ("  -o,--output TEXT REQUIRED   output image ...", "  --smooth   subdivide ...").
/// Only that names column is read: descriptions mention other options and sbatch's, and their
/// continuation lines are indented by the whole name column. A flag's "{default}" is cut off.
std::set<std::string> longOptionsOf(const std::string& help) {
  std::set<std::string> options;
  for (const std::string& line : linesOf(help)) {
    if (line.rfind("  -", 0) != 0) continue;
    const std::size_t namesEnd = std::min(line.find(' ', 2), line.size());
    std::istringstream names(line.substr(2, namesEnd - 2));
    for (std::string name; std::getline(names, name, ',');) {
      if (name.rfind("--", 0) != 0) continue;
      std::size_t end = 2;
      while (end < name.size() && isNameChar(name[end])) ++end;
      if (end > 2) options.insert(name.substr(0, end));
    }
  }
  return options;
}

/// The verbs `gridifs --help` lists; fails the test (empty result) when there is no such list.
std::vector<std::string> listedVerbs() {
  const CommandResult r = runGridifs("--help");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::vector<std::string> verbs = verbsOf(r.out);
  // An anchor: without it a help whose format changed would list nothing and check nothing.
  if (std::find(verbs.begin(), verbs.end(), "render") == verbs.end()) {
    ADD_FAILURE() << "found no verb list (with render in it) in the output of gridifs --help:\n" << r.out;
    return {};
  }
  return verbs;
}

TEST(CliDocs, NamesEveryVerbTheHelpLists) {
  const std::string doc = slurp(kCliDoc);
  ASSERT_FALSE(doc.empty()) << "cannot read " << kCliDoc.string();
  const std::vector<std::string> verbs = listedVerbs();
  ASSERT_FALSE(verbs.empty());
  std::vector<std::string> missing;
  for (const std::string& verb : verbs)
    if (!mentions(doc, "gridifs " + verb)) missing.push_back("gridifs " + verb);
  EXPECT_TRUE(missing.empty()) << "docs/CLI.md does not mention these verbs of gridifs --help: " << joined(missing);
}

TEST(CliDocs, NamesEveryLongOptionOfEveryVerb) {
  const std::string doc = slurp(kCliDoc);
  ASSERT_FALSE(doc.empty()) << "cannot read " << kCliDoc.string();
  const std::vector<std::string> verbs = listedVerbs();
  ASSERT_FALSE(verbs.empty());
  for (const std::string& verb : verbs) {
    SCOPED_TRACE("gridifs " + verb + " --help");
    const CommandResult r = runGridifs(quote(verb) + " --help");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::set<std::string> options = longOptionsOf(r.out);
    // Every verb has --help: without it the page was not read as a CLI11 help page.
    if (options.count("--help") == 0) {
      ADD_FAILURE() << "found no option list (with --help in it) in the output of gridifs " << verb << " --help:\n"
                    << r.out;
      continue;
    }
    std::vector<std::string> missing;
    for (const std::string& option : options)
      if (!mentions(doc, option)) missing.push_back(option);
    EXPECT_TRUE(missing.empty()) << "gridifs " << verb
                                 << " --help lists options that docs/CLI.md does not mention: " << joined(missing);
  }
}

}  // namespace
}  // namespace gridifs

#include "cli/generate_command.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>

#include "cli/arguments.h"
#include "io/write_sites.h"
#include "reference/site_generators.h"

namespace apollonius {

const char* const generate_usage =
    "usage: apollonius3d generate KIND --n N --seed S [-o OUT]\n"
    "       apollonius3d generate --list\n"
    "  Writes N sites (1 to 1000000) of the reproducible family KIND from the seed S (0 to 2^64 - 1) as\n"
    "  balls text 'x y z w', each number printed round-trip: the very sites the tests generate. --list\n"
    "  names and describes every KIND.\n";

namespace {

// A bound on what a command line can ask for: a million sites are about 15 MB of text and seconds of work.
constexpr std::uint64_t kMaxGeneratedSites = 1000000;

struct Generate_command {
  bool list = false;  // --list: the families and their descriptions, nothing generated
  Site_family family = Site_family::uniform;
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  std::string output;  // empty: standard output
};

Generate_command parse_generate(const std::vector<std::string>& args) {
  Generate_command command;
  std::optional<std::string> family, count, seed;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--list") {
      if (args.size() != 2) throw Usage_error("generate --list takes no other arguments");
      command.list = true;
    } else if (a == "-o" || a == "--output") {
      command.output = option_value(args, i);
    } else if (a == "--n") {
      count = option_value(args, i);
    } else if (a == "--seed") {
      seed = option_value(args, i);
    } else if (a.size() > 1 && a[0] == '-') {
      throw Usage_error("unknown option '" + a + "'");
    } else if (!family) {
      family = a;
    } else {
      throw Usage_error("unexpected argument '" + a + "'");
    }
  }
  if (command.list) return command;
  if (!family) throw Usage_error("missing KIND (generate --list names them)");
  if (!count) throw Usage_error("missing --n N");
  if (!seed) throw Usage_error("missing --seed S");
  try {
    command.family = site_family_from_name(*family);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(std::string(e.what()) + " (generate --list names them)");
  }
  command.count = parse_option_integer(*count, "--n", 1, kMaxGeneratedSites);  // the reader refuses an empty input
  command.seed = parse_option_integer(*seed, "--seed", 0, std::numeric_limits<std::uint64_t>::max());
  return command;
}

void print_site_families(std::ostream& out) {
  std::size_t width = 0;
  for (const Site_family_description& d : kSiteFamilies) width = std::max(width, std::strlen(d.name));
  for (const Site_family_description& d : kSiteFamilies)
    out << d.name << std::string(width + 2 - std::strlen(d.name), ' ') << d.summary << '\n';
}

}  // namespace

int run_generate(const std::vector<std::string>& args, std::ostream& out) {
  const Generate_command command = parse_generate(args);
  if (command.list) {
    print_site_families(out);
    return 0;
  }
  const std::vector<Site> sites = generate_sites(command.family, command.count, command.seed);
  const std::string provenance = std::string("apollonius3d generate ") + name_of(command.family) + " --n " +
                                 std::to_string(command.count) + " --seed " + std::to_string(command.seed);
  write_command_output(command.output, out, [&](std::ostream& o) { write_sites_text(o, sites, provenance); });
  return 0;
}

}  // namespace apollonius

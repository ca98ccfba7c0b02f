#include "cli/generate_command.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

#include "io/write_sites.h"
#include "reference/site_generators.h"

namespace apollonius {
namespace {

// A bound on what a command line can ask for: a million sites are about 15 MB of text and seconds of work.
constexpr std::uint64_t kMaxGeneratedSites = 1000000;

struct Generate_command {
  bool list = false;  // the families and their descriptions, nothing generated
  std::string family;
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  std::string output;
  CLI::Option* count_option = nullptr;
  CLI::Option* seed_option = nullptr;
};

void print_site_families(std::ostream& out) {
  std::size_t width = 0;
  for (const Site_family_description& d : kSiteFamilies) width = std::max(width, std::strlen(d.name));
  for (const Site_family_description& d : kSiteFamilies)
    out << d.name << std::string(width + 2 - std::strlen(d.name), ' ') << d.summary << '\n';
}

int run(const Generate_command& command, std::ostream& out) {
  if (command.list) {
    if (!command.family.empty() || command.count_option->count() > 0 || command.seed_option->count() > 0 ||
        !command.output.empty())
      throw Usage_error("generate --list takes no other arguments");
    print_site_families(out);
    return EXIT_OK;
  }
  if (command.family.empty()) throw Usage_error("missing KIND (generate --list names them)");
  if (command.count_option->count() == 0) throw Usage_error("missing --n N");
  if (command.seed_option->count() == 0) throw Usage_error("missing --seed S");
  Site_family family;
  try {
    family = site_family_from_name(command.family);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(std::string(e.what()) + " (generate --list names them)");
  }
  const std::vector<Site> sites = generate_sites(family, command.count, command.seed);
  const std::string provenance = "apollonius3d generate " + command.family + " --n " + std::to_string(command.count) +
                                 " --seed " + std::to_string(command.seed);
  write_command_output(command.output, out, [&](std::ostream& o) { write_sites_text(o, sites, provenance); });
  return EXIT_OK;
}

}  // namespace

Command_run add_generate_command(CLI::App& app) {
  auto command = std::make_shared<Generate_command>();
  CLI::App* sub = app.add_subcommand(
      "generate",
      "Writes N sites of the reproducible family KIND from the seed S as balls text 'x y z w', each number\n"
      "printed round-trip: the very sites the tests generate, so that a failing test case reruns from the\n"
      "command line.");
  sub->add_option("KIND", command->family, "the family (--list names them)");
  command->count_option = sub->add_option("--n", command->count, "the number of sites")
                              ->check(integer_in_range(1, kMaxGeneratedSites))
                              ->type_name("N");
  command->seed_option = sub->add_option("--seed", command->seed, "the seed, 0 to 2^64 - 1")
                             ->check(integer_in_range(0, std::numeric_limits<std::uint64_t>::max()))
                             ->type_name("S");
  add_output_option(*sub, command->output);
  sub->add_flag("--list", command->list, "name and describe every family");
  return [command](std::ostream& out, std::ostream&) { return run(*command, out); };
}

}  // namespace apollonius

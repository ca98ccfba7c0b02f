#include "cli/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "brute_force_diagram.h"
#include "octree_diagram.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/read_sites.h"
#include "io/write_sites.h"
#include "io/write_vertices.h"
#include "predicate_counter.h"
#include "site_generators.h"

namespace apollonius {
namespace {

constexpr const char* kUsage =
    "usage: apollonius3d vertices INPUT [-o OUT] [--format text|json] [--algorithm octree|brute]\n"
    "                             [--threads N] [--box X0 Y0 Z0 X1 Y1 Z1] [--stats]\n"
    "                             [--keep-hydrogens] [--keep-waters]\n"
    "       apollonius3d generate KIND --n N --seed S [-o OUT]\n"
    "       apollonius3d generate --list\n"
    "vertices: prints every vertex of the Apollonius diagram in R^3 (or in the closed --box): its\n"
    "  tie-set site indices (0-based), then x y z r. --algorithm brute is the O(n^5) reference.\n"
    "  INPUT: balls text 'x y z w', vdrc .txt, PDB/mmCIF (optionally .gz), or - for stdin\n"
    "generate: writes N sites (1 to 1000000) of the reproducible family KIND from the seed S\n"
    "  (0 to 2^64 - 1) as balls text 'x y z w', each number printed round-trip: the very sites the\n"
    "  tests generate. --list names and describes every KIND.\n"
    "exit codes: 0 ok, 2 usage or input error, 3 internal error\n";

// A bound on what a command line can ask for: a million sites are about 15 MB of text and seconds of work.
constexpr std::uint64_t kMaxGeneratedSites = 1000000;

struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Vertices_command {
  std::string input;
  std::string output;  // empty: standard output
  std::string format = "text";
  bool format_given = false;
  bool stats = false;
  bool brute_force = false;
  int threads = 1;
  std::optional<Axis_box> box;
  Read_options read_options;
};

struct Generate_command {
  bool list = false;  // --list: the families and their descriptions, nothing generated
  Site_family family = Site_family::uniform;
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  std::string output;  // empty: standard output
};

double parse_number(const std::string& text, const std::string& option) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw Usage_error("option " + option + " needs finite numbers, not '" + text + "'");
  return value;
}

std::uint64_t parse_unsigned(const std::string& text, const std::string& option, std::uint64_t min, std::uint64_t max) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < min || value > max)
    throw Usage_error("option " + option + " needs an integer from " + std::to_string(min) + " to " +
                      std::to_string(max) + ", not '" + text + "'");
  return value;
}

// The value of the option args[i], which the caller skips by the advanced i.
const std::string& value_of(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw Usage_error("option " + args[i] + " needs a value");
  return args[++i];
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Vertices_command parse_vertices(const std::vector<std::string>& args) {
  Vertices_command command;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") {
      command.output = value_of(args, i);
    } else if (a == "--format") {
      command.format = value_of(args, i);
      command.format_given = true;
      if (command.format != "text" && command.format != "json")
        throw Usage_error("unknown format '" + command.format + "' (text or json)");
    } else if (a == "--algorithm") {
      const std::string& algorithm = value_of(args, i);
      if (algorithm != "brute" && algorithm != "octree")
        throw Usage_error("unknown algorithm '" + algorithm + "' (octree or brute)");
      command.brute_force = algorithm == "brute";
    } else if (a == "--threads") {
      const double threads = parse_number(value_of(args, i), a);
      if (threads < 1 || threads > 1024 || threads != std::floor(threads))
        throw Usage_error("option --threads needs an integer from 1 to 1024");
      command.threads = static_cast<int>(threads);
    } else if (a == "--box") {
      if (i + 6 >= args.size()) throw Usage_error("option --box needs 6 numbers X0 Y0 Z0 X1 Y1 Z1");
      Axis_box box;
      for (int k = 0; k < 6; ++k) (k < 3 ? box.lo[k] : box.hi[k - 3]) = parse_number(args[++i], a);
      for (int k = 0; k < 3; ++k)
        if (!(box.lo[k] <= box.hi[k])) throw Usage_error("option --box needs X0 <= X1, Y0 <= Y1, Z0 <= Z1");
      command.box = box;
    } else if (a == "--stats") {
      command.stats = true;
    } else if (a == "--keep-hydrogens") {
      command.read_options.keep_hydrogens = true;
    } else if (a == "--keep-waters") {
      command.read_options.keep_waters = true;
    } else if (a.size() > 1 && a[0] == '-') {
      throw Usage_error("unknown option '" + a + "'");
    } else if (command.input.empty()) {
      command.input = a;
    } else {
      throw Usage_error("unexpected argument '" + a + "'");
    }
  }
  if (command.input.empty()) throw Usage_error("missing INPUT");
  if (!command.format_given && ends_with(command.output, ".json")) command.format = "json";
  return command;
}

Generate_command parse_generate(const std::vector<std::string>& args) {
  Generate_command command;
  std::optional<std::string> family, count, seed;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--list") {
      if (args.size() != 2) throw Usage_error("generate --list takes no other arguments");
      command.list = true;
    } else if (a == "-o" || a == "--output") {
      command.output = value_of(args, i);
    } else if (a == "--n") {
      count = value_of(args, i);
    } else if (a == "--seed") {
      seed = value_of(args, i);
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
  command.count = parse_unsigned(*count, "--n", 1, kMaxGeneratedSites);  // the reader refuses an empty input
  command.seed = parse_unsigned(*seed, "--seed", 0, std::numeric_limits<std::uint64_t>::max());
  return command;
}

// Standard output (path empty) gets nothing unless all of the text is ready; a file is written atomically.
void write_output(const std::string& path, std::ostream& out, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) {
    std::ostringstream buffer;
    write(buffer);
    out << buffer.str() << std::flush;
    return;
  }
  try {
    write_file_atomically(path, write);
  } catch (const std::runtime_error& e) {
    throw Usage_error(e.what());
  }
}

void print_statistics(std::ostream& err, const std::vector<Predicate_statistics>& stats) {
  err << "predicate evaluations exact_stages\n";
  for (const Predicate_statistics& s : stats) err << s.name << ' ' << s.evaluations << ' ' << s.exact_stages << '\n';
}

int run_vertices(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Vertices_command command = parse_vertices(args);
  const Site_input input = read_sites(command.input, command.read_options);
  reset_predicate_statistics();
  Diagram diagram = command.brute_force ? brute_force_diagram(input.sites)
                                        : octree_diagram(input.sites, Octree_options{command.threads});
  if (command.box) restrict_to_box(diagram, *command.box);
  const std::vector<Predicate_statistics> stats = predicate_statistics();

  const std::function<void(std::ostream&)> write = [&](std::ostream& o) {
    if (command.format == "json")
      write_vertices_json(o, diagram, command.stats ? &stats : nullptr);
    else
      write_vertices_text(o, diagram);
  };
  write_output(command.output, out, write);
  if (command.stats) print_statistics(err, stats);
  return EXIT_OK;
}

void print_site_families(std::ostream& out) {
  std::size_t width = 0;
  for (const Site_family_description& d : kSiteFamilies) width = std::max(width, std::strlen(d.name));
  for (const Site_family_description& d : kSiteFamilies)
    out << d.name << std::string(width + 2 - std::strlen(d.name), ' ') << d.summary << '\n';
}

int run_generate(const std::vector<std::string>& args, std::ostream& out) {
  const Generate_command command = parse_generate(args);
  if (command.list) {
    print_site_families(out);
    return EXIT_OK;
  }
  const std::vector<Site> sites = generate_sites(command.family, command.count, command.seed);
  const std::string provenance = std::string("apollonius3d generate ") + name_of(command.family) + " --n " +
                                 std::to_string(command.count) + " --seed " + std::to_string(command.seed);
  write_output(command.output, out, [&](std::ostream& o) { write_sites_text(o, sites, provenance); });
  return EXIT_OK;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw Usage_error("missing command");
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      out << kUsage;
      return EXIT_OK;
    }
    if (args[0] == "vertices") return run_vertices(args, out, err);
    if (args[0] == "generate") return run_generate(args, out);
    throw Usage_error("unknown command '" + args[0] + "'");
  } catch (const Usage_error& e) {
    err << "apollonius3d: " << e.what() << '\n' << kUsage;
    return EXIT_BAD_INPUT;
  } catch (const Input_error& e) {
    err << "apollonius3d: " << e.what() << '\n';
    return EXIT_BAD_INPUT;
  } catch (const std::exception& e) {
    err << "apollonius3d: internal error: " << e.what() << '\n';
    return EXIT_INTERNAL_ERROR;
  }
}

}  // namespace apollonius

// Reading sites (balls, vdrc, PDB, mmCIF), bad input, atomic output files, and the vertex writers.
#include <doctest/doctest.h>
#include <unistd.h>
#include <zlib.h>

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <tuple>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/chunked_buffer.h"
#include "io/input_error.h"
#include "io/json_input.h"
#include "io/json_output.h"
#include "io/json_stream.h"
#include "io/read_sites.h"
#include "io/read_structure.h"
#include "io/round_trip.h"
#include "io/write_vertices.h"
#include "predicates/vertices_of.h"

namespace fs = std::filesystem;
using namespace apollonius;

namespace {

// A fresh directory for one test, removed with everything in it at the end of the test.
class Temporary_directory {
 public:
  Temporary_directory() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("apollonius_test_io_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  Temporary_directory(const Temporary_directory&) = delete;
  Temporary_directory& operator=(const Temporary_directory&) = delete;
  ~Temporary_directory() { fs::remove_all(path_); }

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(file(name), std::ios::binary) << content;
    return file(name);
  }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename().string());
    return names;
  }

 private:
  fs::path path_;
};

std::string file_content(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_gzip(const std::string& path, const std::string& content) {
  gzFile file = gzopen(path.c_str(), "wb");
  REQUIRE(file != nullptr);
  REQUIRE(gzwrite(file, content.data(), static_cast<unsigned>(content.size())) == static_cast<int>(content.size()));
  REQUIRE(gzclose(file) == Z_OK);
}

const Read_options default_options;

Site_input read_text(const std::string& content, const Read_options& options = default_options) {
  return read_sites_from_text(content, "input.txt", options);
}

// Runs read and checks that it throws an Input_error with this file, line and a reason containing reason_part.
template <class Read>
void check_input_error(const Read& read, const std::string& file, std::size_t line, const std::string& reason_part) {
  try {
    read();
    FAIL("no Input_error; expected " << file << ":" << line << ": ..." << reason_part);
  } catch (const Input_error& e) {
    CHECK(e.file() == file);
    CHECK(e.line() == line);
    CHECK_MESSAGE(e.reason().find(reason_part) != std::string::npos, e.what());
  }
}

void check_text_error(const std::string& content, std::size_t line, const std::string& reason_part) {
  check_input_error([&] { read_text(content); }, "input.txt", line, reason_part);
}

// Residue 1 (ALA) with a hydrogen, atom CB in two alternate locations, a ligand, and a water.
const char* const small_pdb =
    "HEADER    TEST\n"
    "ATOM      1  N   ALA A   1       1.000   2.000   3.000  1.00  0.00           N\n"
    "ATOM      2  CA  ALA A   1       2.000   2.000   3.000  1.00  0.00           C\n"
    "ATOM      3  CB AALA A   1       3.000   2.000   3.000  0.50  0.00           C\n"
    "ATOM      4  CB BALA A   1       3.500   2.000   3.000  0.50  0.00           C\n"
    "ATOM      5  H   ALA A   1       0.500   2.000   3.000  1.00  0.00           H\n"
    "HETATM    6 SE   SE  A 101       5.000   5.000   5.000  1.00  0.00          SE\n"
    "HETATM    7  O   HOH A 201       9.000   9.000   9.000  1.00  0.00           O\n"
    "END\n";

// The first two atoms of pept.pdb as a minimal mmCIF.
const char* const small_mmcif =
    "data_small\n"
    "#\n"
    "loop_\n"
    "_atom_site.group_PDB\n"
    "_atom_site.id\n"
    "_atom_site.type_symbol\n"
    "_atom_site.label_atom_id\n"
    "_atom_site.label_alt_id\n"
    "_atom_site.label_comp_id\n"
    "_atom_site.label_asym_id\n"
    "_atom_site.label_entity_id\n"
    "_atom_site.label_seq_id\n"
    "_atom_site.Cartn_x\n"
    "_atom_site.Cartn_y\n"
    "_atom_site.Cartn_z\n"
    "_atom_site.occupancy\n"
    "_atom_site.B_iso_or_equiv\n"
    "_atom_site.auth_seq_id\n"
    "_atom_site.auth_asym_id\n"
    "_atom_site.pdbx_PDB_model_num\n"
    "ATOM 1 N N  . ASP A 1 1 4.868 -17.809 25.188 1.00 34.37 1 E 1\n"
    "ATOM 2 C CA . ASP A 1 1 3.984 -16.723 25.698 1.00 33.85 1 E 1\n"
    "#\n";

const Site pept_first{4.868, -17.809, 25.188, 1.55};
const Site pept_second{3.984, -16.723, 25.698, 1.70};

}  // namespace

// write_round_trip's integer path against std::to_chars (printf's %.17g) on doubles of every kind: random
// bit patterns, random values across the fast path's range and its edges, short decimals, integers,
// powers of ten and their neighbours, and values whose 18th digit is an exact tie.
TEST_CASE("round_trip prints every double as %.17g does") {
  std::mt19937_64 random(17);
  std::size_t checked = 0;
  const auto check = [&](double x) {
    char expected[32], actual[32];
    const std::string reference(expected, std::to_chars(expected, expected + 32, x, std::chars_format::general, 17).ptr);
    const std::string printed(actual, write_round_trip(actual, x));
    CAPTURE(x);
    CHECK(printed == reference);
    ++checked;
  };
  for (int i = 0; i < 300000; ++i) {
    const std::uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    check(x);
    check(std::ldexp(std::uniform_real_distribution<double>(0.5, 1)(random), static_cast<int>(random() % 120) - 60));
    check(-std::uniform_real_distribution<double>(-100, 100)(random));
    check(static_cast<double>(random() % 100000000000000000ull));
    check(static_cast<double>(random() % 1000000) / 1000);  // short decimals
    check(std::ldexp(static_cast<double>(random() % (1ull << 53)), -static_cast<int>(random() % 110)));  // dyadic: exact ties
  }
  for (int k = -20; k <= 20; ++k) {
    const double p = std::pow(10.0, k);
    for (double x : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e300), -p, 0.5 * p, 5 * p, 9.9999999999999999 * p})
      check(x);
  }
  for (double x : {0.0, -0.0, 1.0, 1e-14, 1e17, 0.1, 0.3, 2.5, 1e300, 5e-324, -2.2250738585072014e-308,
                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()})
    check(x);
  CHECK(checked > 1800000);
}

TEST_CASE("Input_error names the file, the line if any, and the reason") {
  CHECK(std::string(Input_error("a.txt", 3, "bad").what()) == "a.txt:3: bad");
  CHECK(std::string(Input_error("a.txt", 0, "empty").what()) == "a.txt: empty");
}

TEST_CASE("balls text: comments, blank lines, CRLF, Voronota annotations") {
  const Site_input input = read_text(
      "# x y z r\r\n"
      "\r\n"
      "4.868 -17.809 25.188 1.55 # 1 E 1 ASP N . .\r\n"
      "   # indented comment\r\n"
      "\t-1.5\t2e1  +3 0.1");
  CHECK(input.format == Input_format::balls);
  REQUIRE(input.sites.size() == 2);
  CHECK(input.sites[0] == pept_first);
  CHECK(input.sites[1] == Site{-1.5, 20, 3, 0.1});  // each field the nearest double to its text
}

TEST_CASE("vdrc: count line, then id x y z r; ids ignored, file order kept") {
  const Site_input input = read_sites(APOLLONIUS_TEST_DATA "/vdrc/ANO3_3CONNECT.txt", default_options);
  CHECK(input.format == Input_format::vdrc);
  REQUIRE(input.sites.size() == 9);
  CHECK(input.sites.front() == Site{-31, 0, 0, 25});
  CHECK(input.sites.back() == Site{0, -100, 1, 5});
}

TEST_CASE("balls and vdrc are told apart by content, whatever the extension") {
  Temporary_directory directory;
  const Site_input balls = read_sites(directory.write("x.txt", "1 2 3 4\n"), default_options);
  CHECK(balls.format == Input_format::balls);
  CHECK(balls.sites == std::vector<Site>{{1, 2, 3, 4}});
  const Site_input vdrc = read_sites(directory.write("y.dat", "1\n7 1 2 3 4\n"), default_options);
  CHECK(vdrc.format == Input_format::vdrc);
  CHECK(vdrc.sites == std::vector<Site>{{1, 2, 3, 4}});
  const Site_input pdb = read_sites(directory.write("z.txt", small_pdb), default_options);
  CHECK(pdb.format == Input_format::structure);
  CHECK(pdb.sites.size() == 4);
}

TEST_CASE("pept.pdb: 107 atoms with Bondi radii") {
  const Site_input input = read_sites(APOLLONIUS_EXAMPLES "/pept.pdb", default_options);
  CHECK(input.format == Input_format::structure);
  REQUIRE(input.sites.size() == 107);
  CHECK(input.sites[0] == pept_first);
  CHECK(input.sites[1] == pept_second);
}

TEST_CASE("a gzipped PDB file reads the same as the plain one") {
  Temporary_directory directory;
  const std::string gzipped = directory.file("pept.PDB.GZ");
  write_gzip(gzipped, file_content(APOLLONIUS_EXAMPLES "/pept.pdb"));
  CHECK(read_sites(gzipped, default_options).sites ==
        read_sites(APOLLONIUS_EXAMPLES "/pept.pdb", default_options).sites);
}

TEST_CASE("mmCIF, from a file, from a gzipped file and by content") {
  Temporary_directory directory;
  const std::vector<Site> expected{pept_first, pept_second};
  CHECK(read_sites(directory.write("small.cif", small_mmcif), default_options).sites == expected);
  write_gzip(directory.file("small.mmcif.gz"), small_mmcif);
  CHECK(read_sites(directory.file("small.mmcif.gz"), default_options).sites == expected);
  const Site_input by_content = read_text(small_mmcif);
  CHECK(by_content.format == Input_format::structure);
  CHECK(by_content.sites == expected);
}

TEST_CASE("structures: hydrogens and waters left out unless kept; one conformer; ligands kept") {
  const Site n{1, 2, 3, 1.55}, ca{2, 2, 3, 1.70}, cb{3, 2, 3, 1.70}, h{0.5, 2, 3, 1.20};
  const Site selenium{5, 5, 5, 1.90}, water{9, 9, 9, 1.52};
  CHECK(read_text(small_pdb).sites == std::vector<Site>{n, ca, cb, selenium});
  Read_options options;
  options.keep_hydrogens = true;
  CHECK(read_text(small_pdb, options).sites == std::vector<Site>{n, ca, cb, h, selenium});
  options.keep_waters = true;
  CHECK(read_text(small_pdb, options).sites == std::vector<Site>{n, ca, cb, h, selenium, water});
  options.keep_hydrogens = false;
  CHECK(read_text(small_pdb, options).sites == std::vector<Site>{n, ca, cb, selenium, water});
}

TEST_CASE("atom labels: one per site when asked for, in the order of the sites") {
  Read_options options;
  CHECK(read_text(small_pdb, options).labels.empty());
  options.atom_labels = true;
  options.keep_hydrogens = true;
  const Site_input input = read_text(small_pdb, options);
  REQUIRE(input.labels.size() == input.sites.size());
  REQUIRE(input.labels.size() == 5);  // N CA CB(A) H SE
  const Atom_label& ca = input.labels[1];
  CHECK(ca.chain == "A");
  CHECK(ca.residue_name == "ALA");
  CHECK(ca.residue_number == 1);
  CHECK(ca.insertion_code == ' ');
  CHECK(ca.atom_name == "CA");
  CHECK(ca.element == "C");
  CHECK(ca.alternate_location == ' ');
  CHECK(ca.serial == 2);
  CHECK(input.labels[2].atom_name == "CB");
  CHECK(input.labels[2].alternate_location == 'A');
  CHECK(input.labels[3].element == "H");
  const Atom_label& selenium = input.labels[4];
  CHECK(selenium.residue_name == "SE");
  CHECK(selenium.residue_number == 101);
  CHECK(selenium.element == "Se");
  CHECK(selenium.serial == 6);

  Temporary_directory directory;
  const Site_input cif = read_sites(directory.write("small.cif", small_mmcif), options);
  REQUIRE(cif.labels.size() == 2);
  CHECK(cif.labels[0].chain == "E");
  CHECK(cif.labels[0].residue_name == "ASP");
  CHECK(cif.labels[0].atom_name == "N");
  CHECK(cif.labels[1].serial == 2);
  const Site_input pept = read_sites(APOLLONIUS_EXAMPLES "/pept.pdb", options);
  CHECK(pept.labels.size() == pept.sites.size());
  CHECK(read_sites(APOLLONIUS_TEST_DATA "/pept.balls", options).labels.empty());
}

TEST_CASE("sites from arrays: checked as files are") {
  const double centres[] = {0, 1, 2, 3, 4, 5};
  const double weights[] = {0.5, -1};
  CHECK(sites_from_arrays(centres, weights, 2) == std::vector<Site>{{0, 1, 2, 0.5}, {3, 4, 5, -1}});
  check_input_error([&] { sites_from_arrays(centres, weights, 0); }, "centres", 0, "empty input: no sites");
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const double bad_centres[] = {0, 1, 2, 3, 4, nan};
  check_input_error([&] { sites_from_arrays(bad_centres, weights, 2); }, "centres", 0,
                    "site 1, z: not a finite number: nan");
  const double bad_weights[] = {0.5, -inf};
  check_input_error([&] { sites_from_arrays(centres, bad_weights, 2); }, "weights", 0,
                    "site 1: not a finite number: -inf");
  try {
    sites_from_arrays(bad_centres, weights, 2);
  } catch (const Input_error& e) {
    CHECK(std::string(e.what()) == "centres: site 1, z: not a finite number: nan");
  }
}

TEST_CASE("standard input is read for \"-\" and named <stdin>") {
  std::istringstream fake_stdin("1 2 3 4\n0 0 0\n");
  struct Restore_stdin {
    std::streambuf* real;
    ~Restore_stdin() { std::cin.rdbuf(real); }
  } restore{std::cin.rdbuf(fake_stdin.rdbuf())};
  check_input_error([] { read_sites("-", default_options); }, "<stdin>", 2, "expected 4 fields");
}

TEST_CASE("bad numbers") {
  check_text_error("1 2 nan 4\n", 1, "not a finite number: 'nan'");
  check_text_error("1 2 3 4\n1 2 3 -inf\n", 2, "not a finite number: '-inf'");
  check_text_error("1 2 3 4\n1 2 3 1e400\n", 2, "out of double range: '1e400'");
  check_text_error("1 2 3 4\n1 2 three 4\n", 2, "not a number: 'three'");
  check_text_error("1 2 3 4\n1.5x 2 3 4\n", 2, "not a number: '1.5x'");
  check_text_error("1 2 3 4\n1 2 3 4,\n", 2, "not a number: '4,'");
}

TEST_CASE("bad field counts") {
  check_text_error("1 2 3\n", 1, "expected 4 fields 'x y z w', found 3");
  check_text_error("1 2 3 4\n\n1 2 3 4 5\n", 3, "expected 4 fields 'x y z w', found 5");
  check_text_error("2\n1 0 0 0 1\n2 0 0 1\n", 3, "expected 5 fields 'id x y z r', found 4");
}

TEST_CASE("vdrc count mismatch") {
  check_text_error("3\n1 0 0 0 1\n2 1 0 0 1\n", 3, "expected 3 balls, found 2");
  check_text_error("1\n1 0 0 0 1\n2 1 0 0 1\n", 3, "expected 1 balls, found more");
  check_text_error("0\n", 0, "empty input: no sites");
  check_text_error("1\nA 0 0 0 1\n", 2, "not an integer id: 'A'");
}

TEST_CASE("unrecognized, empty and binary input") {
  check_text_error("hello world\n", 1, "unrecognized input format");
  check_text_error("", 0, "empty input: no sites");
  check_text_error("# only\n   # comments\n\n", 0, "empty input: no sites");
  check_text_error(std::string("1 2 3 4\n\0\0\x01 junk", 16), 2, "binary data (byte 0x00)");
}

TEST_CASE("missing, unreadable and empty files") {
  Temporary_directory directory;
  const std::string missing = directory.file("missing.txt");
  check_input_error([&] { read_sites(missing, default_options); }, missing, 0, "cannot open: No such file");
  const std::string missing_pdb = directory.file("missing.pdb.gz");
  check_input_error([&] { read_sites(missing_pdb, default_options); }, missing_pdb, 0, "cannot open: No such file");
  const std::string folder = directory.file("folder.pdb");
  fs::create_directory(folder);
  check_input_error([&] { read_sites(folder, default_options); }, folder, 0, "cannot open: Is a directory");
  const std::string empty = directory.write("empty.txt", "");
  check_input_error([&] { read_sites(empty, default_options); }, empty, 0, "empty input: no sites");
}

TEST_CASE("structures without atoms, and malformed structures") {
  Temporary_directory directory;
  const std::string no_atoms = directory.write("no_atoms.pdb", "HEADER    EMPTY\nEND\n");
  check_input_error([&] { read_sites(no_atoms, default_options); }, no_atoms, 0, "no atoms");
  check_text_error("HEADER    EMPTY\nEND\n", 0, "no atoms");
  check_text_error("data_empty\n_cell.length_a 10\n", 0, "no atoms");
  check_text_error("HEADER    SHORT\nATOM      1  N   A\n", 2, "too short");
  check_text_error("data_broken\n_cell.length_a 10\n'unterminated\n", 3, "parse error");
}

TEST_CASE("atomic writes: content appears whole, or not at all") {
  Temporary_directory directory;
  const std::string path = directory.file("out.txt");
  write_file_atomically(path, [](std::ostream& out) { out << "first\n"; });
  CHECK(file_content(path) == "first\n");
  write_file_atomically(path, [](std::ostream& out) { out << "second\n"; });
  CHECK(file_content(path) == "second\n");

  const auto failing_writer = [](std::ostream& out) {
    out << std::string(1 << 20, 'x');  // more than one buffer: part of it reached the temporary file
    throw std::runtime_error("writer failed");
  };
  CHECK_THROWS_WITH(write_file_atomically(path, failing_writer), "writer failed");
  CHECK(file_content(path) == "second\n");
  CHECK(directory.entries() == std::vector<std::string>{"out.txt"});

  const std::string fresh = directory.file("fresh.txt");
  CHECK_THROWS_WITH(write_file_atomically(fresh, failing_writer), "writer failed");
  CHECK(directory.entries() == std::vector<std::string>{"out.txt"});

  const std::string unreachable = directory.file("no_such_directory/out.txt");
  CHECK_THROWS_WITH(write_file_atomically(unreachable, [](std::ostream& out) { out << "x"; }),
                    ("cannot write " + unreachable + ": No such file or directory").c_str());
}

TEST_CASE("vertex writers: text and JSON") {
  // Four unit balls on a regular tetrahedron: one vertex, the centre, at distance sqrt(3) - 1.
  const std::vector<Site> sites{{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}};
  const Quadruple_vertices found = vertices_of(make_quadruple({0, 1, 2, 3}, sites));
  REQUIRE(found.vertices.size() == 1);
  Diagram diagram;
  diagram.site_count = 6;
  // sqrt(3) - 1 to 38 digits, so that the literal is its correctly rounded double (std::sqrt(3.0) - 1 is not).
  const double r = 0.73205080756887729352744634150587236694;
  diagram.vertices.push_back({{0, 1, 2, 3}, found.vertices[0], {0, 0, 0, r}});
  diagram.hidden.push_back({4, 0, true});
  diagram.sites_without_vertex.push_back(5);

  std::ostringstream text;
  write_vertices_text(text, diagram);
  CHECK(text.str() == "0 1 2 3 0 0 0 0.7320508075688773\n");

  std::ostringstream json;
  write_vertices_json(json, diagram, nullptr);
  CHECK(json.str() ==
        "{\n"
        "  \"format\": \"apollonius3d-vertices\",\n"
        "  \"version\": 1,\n"
        "  \"sites\": 6,\n"
        "  \"vertices\": [\n"
        "    {\"sites\":[0,1,2,3],\"x\":0.0,\"y\":0.0,\"z\":0.0,\"r\":0.7320508075688773}\n"
        "  ],\n"
        "  \"hidden_sites\": [\n"
        "    {\"site\":4,\"hidden_by\":0,\"duplicate\":true}\n"
        "  ],\n"
        "  \"sites_without_vertex\": [5]\n"
        "}\n");

  const std::vector<Predicate_statistics> stats{{"vertices_of", 10, 2}, {"say \"hi\"", 0, 0}};
  std::ostringstream with_stats;
  write_vertices_json(with_stats, diagram, &stats);
  CHECK(with_stats.str().find("\"stats\": {\"predicates\":["
                              "{\"name\":\"vertices_of\",\"evaluations\":10,\"exact_stages\":2},"
                              "{\"name\":\"say \\\"hi\\\"\",\"evaluations\":0,\"exact_stages\":0}]}\n}\n") !=
        std::string::npos);
}

TEST_CASE("vertex text writer: the same bytes for every thread count, block boundaries included") {
  const std::vector<Site> sites{{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}};
  const Quadruple_vertices found = vertices_of(make_quadruple({0, 1, 2, 3}, sites));
  REQUIRE(found.vertices.size() == 1);
  // Lines of varied length (tie sets of 4 to 7 sites, values of every binade) across several blocks of the
  // parallel formatting, and sizes just around a block's 2,048 lines.
  std::mt19937_64 random(17);
  for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{2047}, std::size_t{2048},
                                  std::size_t{2049}, std::size_t{20000}}) {
    CAPTURE(count);
    Diagram diagram;
    diagram.site_count = 1000;
    std::string expected;
    for (std::size_t k = 0; k < count; ++k) {
      std::vector<Site_index> tie_set(4 + random() % 4);  // ascending, as a tie set is
      for (std::size_t j = 0; j < tie_set.size(); ++j) tie_set[j] = static_cast<Site_index>(10 * j + random() % 10);
      std::array<double, 4> rounded;
      for (double& x : rounded) x = std::ldexp(static_cast<double>(random() % 1000000) - 500000, static_cast<int>(random() % 200) - 100);
      for (Site_index s : tie_set) expected += std::to_string(s) + ' ';
      char number[32];
      for (int j = 0; j < 4; ++j) expected += std::string(number, write_round_trip(number, rounded[j])) + (j < 3 ? ' ' : '\n');
      diagram.vertices.push_back({tie_set, found.vertices[0], rounded});
    }
    for (const int threads : {1, 2, 8}) {
      CAPTURE(threads);
      std::ostringstream text;
      write_vertices_text(text, diagram, threads);
      CHECK(text.str() == expected);
    }
  }
}

TEST_CASE("vertex writers: non-finite values and empty lists") {
  const std::vector<Site> sites{{1, 1, 1, 1}, {1, -1, -1, 1}, {-1, 1, -1, 1}, {-1, -1, 1, 1}};
  const Quadruple_vertices found = vertices_of(make_quadruple({0, 1, 2, 3}, sites));
  REQUIRE(found.vertices.size() == 1);
  Diagram diagram;
  diagram.site_count = 4;
  diagram.vertices.push_back({{0, 1, 2, 3}, found.vertices[0], {HUGE_VAL, -HUGE_VAL, 1e300, 0.1}});

  std::ostringstream text;
  write_vertices_text(text, diagram);
  CHECK(text.str() == "0 1 2 3 inf -inf 1.0000000000000001e+300 0.10000000000000001\n");

  std::ostringstream json;
  write_vertices_json(json, diagram, nullptr);
  CHECK(json.str().find("\"x\":\"inf\",\"y\":\"-inf\",\"z\":1e+300,\"r\":0.1}") != std::string::npos);
  CHECK(json.str().find("\"hidden_sites\": [],\n  \"sites_without_vertex\": []\n}") != std::string::npos);
}

namespace {

// A random JSON value: numbers of every binade (finite; an infinity is the string json_number makes),
// integers of both signs, strings with escapes, non-ASCII and invalid UTF-8, nested containers.
Json random_json(std::mt19937_64& random, int depth) {
  const int kind = static_cast<int>(random() % (depth > 2 ? 6 : 8));
  switch (kind) {
    case 0: {
      double x;
      do {
        const std::uint64_t bits = random();
        std::memcpy(&x, &bits, sizeof x);
      } while (std::isnan(x));
      if (random() % 3 == 0) x = static_cast<double>(static_cast<int>(random() % 2001) - 1000) / 8;
      return json_number(x);
    }
    case 1: return Json(random() >> (random() % 64));
    case 2: return Json(-static_cast<std::int64_t>(random() >> (1 + random() % 63)));
    case 3: return Json(random() % 2 == 0);
    case 4: return Json(nullptr);
    case 5: {
      const std::string alphabet = std::string("ab \"\\/\n\t\x01\x7f", 10) + "\xc3\xa9" + "\xff";
      std::string text;
      for (int n = static_cast<int>(random() % 6); n > 0; --n) text += alphabet[random() % alphabet.size()];
      return Json(text);
    }
    case 6: {
      Json array = Json::array();
      for (int n = static_cast<int>(random() % 4); n > 0; --n) array.push_back(random_json(random, depth + 1));
      return array;
    }
    default: {
      Json object = Json::object();
      for (int n = static_cast<int>(random() % 4); n > 0; --n)
        object["k" + std::to_string(random() % 5) + (random() % 4 == 0 ? "\"\xe9" : "")] = random_json(random, depth + 1);
      return object;
    }
  }
}

void stream_compact(Json_stream& out, const Json& value) {
  switch (value.type()) {
    case Json::value_t::array:
      out.begin_array();
      for (const Json& element : value) stream_compact(out, element);
      out.end_array();
      break;
    case Json::value_t::object:
      out.begin_object();
      for (const auto& [key, member] : value.items()) {
        out.key(key);
        stream_compact(out, member);
      }
      out.end_object();
      break;
    case Json::value_t::number_float: out.number_or_infinity(value.get<double>()); break;
    case Json::value_t::number_unsigned: out.unsigned_number(value.get<std::uint64_t>()); break;
    case Json::value_t::number_integer: out.integer(value.get<std::int64_t>()); break;
    case Json::value_t::boolean: out.boolean(value.get<bool>()); break;
    case Json::value_t::string: out.string(value.get<std::string>()); break;
    default: out.null();
  }
}

}  // namespace

TEST_CASE("Json_stream writes what write_json_document prints for the same document") {
  const std::uint64_t seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937_64 random(seed);
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    Json document = Json::object();
    for (int n = static_cast<int>(random() % 5); n > 0; --n) {
      Json value = random_json(random, 0);
      if (random() % 2 == 0) {  // a list of lines, or an empty one
        value = Json::array();
        for (int k = static_cast<int>(random() % 4); k > 0; --k) {
          Json element = random_json(random, 1);
          value.push_back(random() % 2 == 0 ? Json::array({element}) : Json{{"e", element}});
        }
      }
      document["m" + std::to_string(random() % 6)] = value;
    }
    std::ostringstream expected, streamed;
    write_json_document(expected, document);
    {
      Json_stream out(streamed);
      for (const auto& [key, value] : document.items()) {
        out.member(key);
        if (value.is_array() && !value.empty() && (value.front().is_object() || value.front().is_array())) {
          out.begin_lines();
          for (const Json& element : value) {
            out.line();
            stream_compact(out, element);
          }
          out.end_lines();
        } else {
          stream_compact(out, value);
        }
      }
      out.finish();
    }
    REQUIRE(streamed.str() == expected.str());
  }
  // Infinities as json_number writes them; more than a buffer's worth of text.
  std::ostringstream expected, streamed;
  Json long_list = Json::array();
  for (int k = 0; k < 20000; ++k) long_list.push_back(Json::array({json_number(k % 3 == 0 ? -HUGE_VAL : HUGE_VAL), k * 0.1}));
  write_json_document(expected, Json{{"l", long_list}});
  {
    Json_stream out(streamed);
    out.member("l");
    out.begin_lines();
    for (int k = 0; k < 20000; ++k) {
      out.line();
      out.begin_array();
      out.number_or_infinity(k % 3 == 0 ? -HUGE_VAL : HUGE_VAL);
      out.number_or_infinity(k * 0.1);
      out.end_array();
    }
    out.end_lines();
    out.finish();
  }
  CHECK(streamed.str() == expected.str());
}

TEST_CASE("JSON: every kind of value, escapes, and the line where each value starts") {
  const Json_document d = parse_json(
      "{\"a\": [1, -0.5e-3,\n true, false, null],\n \"s\": \"q\\\"\\\\\\/\\n\\u00e9\\ud83d\\ude00\",\n\n \"o\": {},"
      " \"n\": 12\n}",
      "j");
  const Json_node v(d.value, d.lines);
  REQUIRE(v.value().is_object());
  CHECK(v.line() == 1);
  const std::optional<Json_node> a = v.member("a");
  REQUIRE(a);
  REQUIRE(a->size() == 5);
  CHECK(a->element(0).value() == 1);
  CHECK(a->element(1).value().get<double>() == -0.5e-3);
  CHECK(a->element(1).line() == 1);  // the number's end was read with the line break after it
  CHECK(a->element(2).value() == true);
  CHECK(a->element(2).line() == 2);
  CHECK(a->element(3).value() == false);
  CHECK(a->element(4).value().is_null());
  CHECK(a->element(4).kind() == std::string("null"));
  CHECK(v.member("s")->value() == "q\"\\/\n\u00e9\U0001F600");
  CHECK(v.member("s")->line() == 3);
  CHECK(v.member("o")->line() == 5);
  CHECK(v.member("o")->value().empty());
  CHECK(v.member("n")->line() == 5);
  CHECK(v.member("n")->kind() == std::string("a number"));
  CHECK_FALSE(v.member("missing"));
  CHECK_FALSE(a->member("a"));  // not an object
}

TEST_CASE("JSON: numbers read as the nearest double, as from_chars reads them") {
  for (const std::string literal : {"0.1", "1e-320", "2.2250738585072011e-308", "1.7976931348623157e308",
                                    "0.30000000000000004", "-4.9406564584124654e-324", "123456789012345678901234567890"}) {
    CAPTURE(literal);
    const Json_document d = parse_json("[" + literal + "]", "j");
    double expected = 0;
    std::from_chars(literal.data(), literal.data() + literal.size(), expected);
    CHECK(d.value[0].get<double>() == expected);
  }
}

TEST_CASE("JSON: malformed documents name their line") {
  for (const auto& [text, line, reason] : std::vector<std::tuple<std::string, std::size_t, std::string>>{
           {"", 1, "unexpected end of input"},
           {"{\n\"a\": 01}", 2, "syntax error"},
           {"[1.]", 1, "syntax error"},
           {"[-]", 1, "syntax error"},
           {"[1e]", 1, "syntax error"},
           {"[1,\n]", 2, "syntax error"},
           {"{\"a\" 1}", 1, "syntax error"},
           {"[\"a\nb\"]", 1, "syntax error"},
           {"[\"\\x\"]", 1, "syntax error"},
           {"[\"\\ud800\"]", 1, "syntax error"},
           {"[tru]", 1, "syntax error"},
           {"{}\n{}", 2, "expected end of input"},
           {"[\"open", 1, "syntax error"},
           {"{\"v\": [],\n\"v\": []}", 2, "duplicate key \"v\""},
           {std::string(65, '[') + std::string(65, ']'), 1, "nested deeper than 64 levels"}}) {
    CAPTURE(text);
    try {
      parse_json(text, "bad.json");
      FAIL("no Input_error");
    } catch (const Input_error& e) {
      CHECK(e.file() == "bad.json");
      CHECK(e.line() == line);
      CHECK(e.reason().find(reason) != std::string::npos);
    }
  }
  CHECK_NOTHROW(parse_json(std::string(64, '[') + std::string(64, ']'), "deep.json"));
}

TEST_CASE("regression: structure_coordinate_not_finite") {
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/structure_coordinate_not_finite.pdb";
  check_input_error([&] { read_sites(file, default_options); }, file, 4,
                    "atom coordinate in columns 31-38: not a finite number: 'nan'");
  check_text_error("ATOM      1  N   ASP A   1       4.868   1e999  25.188  1.00 34.37           N\n", 1,
                   "atom coordinate in columns 39-46: out of double range: '1e999'");
  std::string mmcif = small_mmcif;
  mmcif.replace(mmcif.find("25.188"), 6, "inf");
  check_text_error(mmcif, 0, "not a finite coordinate: atom 1 (N of ASP 1, chain E)");
}

TEST_CASE("regression: gemmi_shift_of_negative_char") {
  // A byte >= 0x80 in a PDB record name: undefined behaviour inside gemmi, let pass in the sanitized
  // builds (CMakeLists.txt); the reader must still answer with an Input_error.
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gemmi_shift_of_negative_char.txt";
  check_input_error([&] { read_sites(file, default_options); }, file, 2, "too short");
}

TEST_CASE("regression: gemmi_ssbond_overread") {
  // Under AddressSanitizer (APOLLONIUS_SANITIZE, scripts/fuzz.sh) the over-read aborted; here the atom is read.
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gemmi_ssbond_overread.pdb";
  const std::vector<Site> sites = read_sites(file, default_options).sites;
  REQUIRE(sites.size() == 1);
  CHECK(sites[0] == Site{1, 2, 3, 1.80});
  CHECK(read_text(file_content(file)).sites == sites);  // the same by content
}

TEST_CASE("regression: gemmi_dbref2_integer_overflow") {
  // Under UndefinedBehaviorSanitizer (APOLLONIUS_SANITIZE, scripts/fuzz.sh) gemmi's int overflow aborted;
  // the DBREF records are now blanked before gemmi reads them, and the atom is read.
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gemmi_dbref2_integer_overflow.pdb";
  const std::vector<Site> sites = read_sites(file, default_options).sites;
  REQUIRE(sites.size() == 1);
  CHECK(sites[0] == Site{1, 2, 3, 1.80});
}

TEST_CASE("regression: gemmi_cif_integer_overflow") {
  // gemmi's mmCIF integers overflowed on ten or more digits (UBSan abort); such values are refused, except
  // in the decimal columns, where a long number is a coordinate like any other.
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gemmi_cif_integer_overflow.cif";
  check_input_error([&] { read_sites(file, default_options); }, file, 0,
                    "number too long for gemmi's integers in _atom_site.auth_seq_id: '1333333333333'");
  std::string mmcif = small_mmcif;
  mmcif.replace(mmcif.find("4.868"), 5, "12345678901.5");
  CHECK(read_text(mmcif).sites.front().x == 12345678901.5);
}

TEST_CASE("regression: gemmi_line_split_at_high_byte") {
  // gemmi took an SSBOND in the middle of a long line, after a byte 0xff, for a record of its own and
  // over-read it (found by fuzz_read_sites). Now lines split as in the file, and line 5's coordinate
  // columns, which gemmi would read as (2, 0, 1), are refused.
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gemmi_line_split_at_high_byte.pdb";
  check_input_error([&] { read_sites(file, default_options); }, file, 5,
                    "atom coordinate in columns 31-38: not a number: '2,4 0.00'");
}

TEST_CASE("PDB atom coordinates: each column field is one whole number") {
  const std::string atom = "ATOM      1  N   ASP A   1       4.868 -17.809  25.188  1.00 34.37           N\n";
  CHECK(read_text(atom).sites == std::vector<Site>{{4.868, -17.809, 25.188, 1.55}});
  for (const auto& [field, reason] : std::vector<std::pair<std::string, std::string>>{
           {"        ", "blank atom coordinate in columns 39-46"},
           {" -17.8x9", "atom coordinate in columns 39-46: not a number: '-17.8x9'"},
           {" -17 809", "atom coordinate in columns 39-46: not a number: '-17 809'"},
           {"     inf", "atom coordinate in columns 39-46: not a finite number: 'inf'"}}) {
    CAPTURE(field);
    std::string line = atom;
    line.replace(38, 8, field);
    check_text_error(line, 1, reason);
  }
}

TEST_CASE("Chunked_buffer holds what an ostringstream holds, across its chunks") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    Chunked_buffer chunks;
    std::ostream through_chunks(&chunks);
    std::ostringstream expected;
    std::size_t written = 0;
    while (written < (std::size_t{5} << 20)) {  // five chunks and some
      const std::size_t length = random() % 3 == 0 ? random() % 3000000 : random() % 40;
      std::string text(length, static_cast<char>('a' + random() % 26));
      if (length == 1) {
        through_chunks.put(text[0]);
        expected.put(text[0]);
      } else {
        through_chunks << text << 1.5 << ' ';
        expected << text << 1.5 << ' ';
      }
      written += length + 4;
    }
    std::ostringstream out;
    chunks.write_to(out);
    REQUIRE(out.str().size() == expected.str().size());
    CHECK(out.str() == expected.str());
  }
  Chunked_buffer empty;
  std::ostringstream out;
  empty.write_to(out);
  CHECK(out.str().empty());
}

// apollonius3d mesh: the PLY header and sizes (binary little-endian and ASCII), site_a < site_b on faces and
// walls numbered below zero, OBJ groups, --quality's five lines, --sites; bad input or parameters: a
// usage line or FILE:LINE: reason, exit 2, and no output file.
#include <doctest/doctest.h>

#include <sstream>

#include "support/cli_helpers.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

const std::string kBalls = "0 0 0 1\n3 0 0 1.2\n0 3 0 0.8\n0 0 3 1\n1.5 1.5 1.5 0.5\n";

struct Ply_header {
  bool binary = false;
  std::size_t vertices = 0, faces = 0, header_bytes = 0;
};

Ply_header read_header(const std::string& content) {
  Ply_header h;
  std::istringstream in(content);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "format") h.binary = second == "binary_little_endian";
    if (first == "element" && second == "vertex") words >> h.vertices;
    if (first == "element" && second == "face") words >> h.faces;
    if (first == "end_header") break;
  }
  h.header_bytes = static_cast<std::size_t>(in.tellg());
  return h;
}

}  // namespace

TEST_CASE("mesh writes binary and ASCII PLY and OBJ, and the quality table") {
  Scratch scratch;
  const std::string balls = scratch.write("balls.txt", kBalls);
  const Cli_result binary = run({"mesh", balls, "-o", scratch.path("m.ply"), "--lloyd", "3", "--quality"});
  REQUIRE(binary.code == EXIT_OK);
  const std::string content = scratch.read("m.ply");
  const Ply_header h = read_header(content);
  CHECK(h.binary);
  CHECK(h.vertices > 100);
  CHECK(content.size() == h.header_bytes + 24 * h.vertices + 25 * h.faces);
  std::istringstream quality(binary.out);
  std::string line;
  std::getline(quality, line);
  CHECK(line.rfind("measure minimum mean", 0) == 0);
  int rows = 0;
  for (const char* name : {"Q_amin", "Q_Ll", "Q_ALS", "Q_Rr", "Q_lr"}) {
    std::string word;
    double minimum, mean;
    REQUIRE(static_cast<bool>(quality >> word >> minimum >> mean));
    CHECK(word == name);
    CHECK(minimum <= mean);
    CHECK(mean > 0.5);
    ++rows;
  }
  CHECK(rows == 5);

  REQUIRE(run({"mesh", balls, "-o", scratch.path("a.ply"), "--lloyd", "3", "--ascii"}).code == EXIT_OK);
  const std::string text = scratch.read("a.ply");
  const Ply_header a = read_header(text);
  CHECK(!a.binary);
  CHECK(a.vertices > 100);
  std::istringstream body(text.substr(a.header_bytes));
  double x, y, z;
  for (std::size_t k = 0; k < a.vertices; ++k) REQUIRE(static_cast<bool>(body >> x >> y >> z));
  std::size_t walls = 0;
  for (std::size_t k = 0; k < a.faces; ++k) {
    int n, u, v, w, site_a, site_b, face_id;
    REQUIRE(static_cast<bool>(body >> n >> u >> v >> w >> site_a >> site_b >> face_id));
    CHECK(n == 3);
    CHECK(site_a < site_b);
    if (site_a < 0) {
      ++walls;
      CHECK(site_a >= -6);
      CHECK(face_id == -1);
    } else {
      CHECK(face_id >= 0);
    }
  }
  CHECK(walls > 0);

  REQUIRE(run({"mesh", balls, "-o", scratch.path("m.obj"), "--lloyd", "0", "--sites", "4"}).code == EXIT_OK);
  const std::string obj = scratch.read("m.obj");
  CHECK(obj.find("\no face_") != std::string::npos);
  CHECK(obj.find("\nf ") != std::string::npos);
  std::istringstream groups(obj);
  while (std::getline(groups, line)) {
    if (line.rfind("o face_", 0) != 0) continue;
    CHECK((line.find("_4") != std::string::npos));  // every face of cell 4
  }

  // The real binary, to standard output's quality table.
  const auto [code, output] = shell(std::string(APOLLONIUS_BINARY) + " mesh '" + balls + "' -o '" +
                                    scratch.path("b.ply") + "' --lloyd 1 --quality");
  CHECK(code == 0);
  CHECK(output.find("Q_Rr") != std::string::npos);
}

TEST_CASE("mesh: bad input and bad parameters exit 2 and write nothing") {
  Scratch scratch;
  const std::string balls = scratch.write("balls.txt", kBalls);
  const std::string bad = scratch.write("bad.txt", "0 0 0 1\n1 2 x 3\n");
  const std::string out = scratch.path("out.ply");
  const std::size_t files = scratch.file_count();
  const Cli_result input = run({"mesh", bad, "-o", out});
  CHECK(input.code == EXIT_BAD_INPUT);
  CHECK(input.err.find("bad.txt:2") != std::string::npos);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--step", "0"},
           {"--step", "-1"},
           {"--step", "nan"},
           {"--box", "0", "0", "0", "0", "1", "1"},
           {"--box", "0", "0", "0", "1", "1"},
           {"--sites", "5"},
           {"--sites", "-1"},
           {"--lloyd", "-1"},
           {"--probe", "-1"},
           {"--probe", "1", "--box", "0", "0", "0", "1", "1", "1"},
       }) {
    std::vector<std::string> command{"mesh", balls, "-o", out};
    command.insert(command.end(), args.begin(), args.end());
    const Cli_result r = run(command);
    CAPTURE(args.front());
    CHECK(r.code == EXIT_BAD_INPUT);
    CHECK(!r.err.empty());
  }
  CHECK(run({"mesh", balls, "-o", scratch.path("out.stl")}).code == EXIT_BAD_INPUT);
  CHECK(run({"mesh", balls, "-o", scratch.path("out.obj"), "--ascii"}).code == EXIT_BAD_INPUT);
  CHECK(run({"mesh", balls}).code == EXIT_BAD_INPUT);
  CHECK(scratch.file_count() == files);  // no output file, no temporary left
}

TEST_CASE("mesh warns on standard error when cells are left open, and only then") {
  Scratch scratch;
  const Cli_result closed =
      run({"mesh", scratch.write("balls.txt", kBalls), "-o", scratch.path("m.ply"), "--lloyd", "2"});
  REQUIRE(closed.code == EXIT_OK);
  CHECK(closed.err.find("not closed") == std::string::npos);
  // 300 balls tangent to one sphere: faces near their common vertex keep crossing chords, and 8 cells stay open.
  const std::string input = std::string(APOLLONIUS_TEST_DATA) + "/regression/mesh_crashed_where_edge_chords_cross.balls";
  const Cli_result open = run({"mesh", input, "-o", scratch.path("open.ply"), "--lloyd", "2", "--stats"});
  REQUIRE(open.code == EXIT_OK);
  CHECK(open.err.find("cells are not closed") != std::string::npos);
  CHECK(open.err.find("open_cells 0\n") == std::string::npos);
  CHECK(scratch.read("open.ply").size() > 0);
}

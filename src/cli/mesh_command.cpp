#include "cli/mesh_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

#include "io/round_trip.h"
#include "io/write_mesh.h"
#include "mesh/diagram_mesh.h"
#include "mesh/mesh_quality.h"
#include "octree/octree_diagram.h"
#include "topology/build_topology.h"
#include "topology/validate_topology.h"

namespace apollonius {
namespace {

struct Mesh_command {
  std::string input;
  std::string output;
  double step = 0;
  std::vector<double> box;  // empty, or X0 Y0 Z0 X1 Y1 Z1
  double probe = 1.4;
  CLI::Option* probe_option = nullptr;
  std::vector<long long> sites;
  int lloyd = 20;
  bool quality = false, ascii = false, stats = false;
  CLI::Option* step_option = nullptr;
  Diagram_options diagram;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int run(const Mesh_command& command, std::ostream& out, std::ostream& err) {
  const bool obj = ends_with(command.output, ".obj");
  if (!obj && !ends_with(command.output, ".ply")) throw Usage_error("-o must name a .ply or .obj file, not '" + command.output + "'");
  if (command.ascii && obj) throw Usage_error("--ascii is for PLY output (OBJ is text)");
  if (command.step_option->count() > 0 && !(command.step > 0))
    throw Usage_error("--step must be a number > 0, not " + round_trip(command.step));
  Mesh_options options;
  options.step = command.step;
  options.threads = command.diagram.threads;
  options.lloyd_iterations = command.lloyd;
  if (!command.box.empty()) {
    options.has_box = true;
    for (int k = 0; k < 3; ++k) {
      options.box.lo[k] = command.box[k], options.box.hi[k] = command.box[k + 3];
      if (!(options.box.lo[k] < options.box.hi[k])) throw Usage_error("--box needs X0 < X1, Y0 < Y1, Z0 < Z1");
    }
  }
  if (command.probe_option->count() > 0) {
    if (!command.box.empty()) throw Usage_error("--box and --probe exclude each other");
    if (!(command.probe >= 0)) throw Usage_error("--probe must be a number >= 0, not " + round_trip(command.probe));
    options.has_probe = true;
    options.probe = command.probe;
  }
  const Site_input input = read_sites(command.input, command.diagram.read_options);
  for (long long s : command.sites) {
    if (s < 0 || static_cast<unsigned long long>(s) >= input.sites.size())
      throw Usage_error("--sites: no site " + std::to_string(s) + " (the input has " + std::to_string(input.sites.size()) +
                        " sites, numbered from 0)");
    options.sites.push_back(static_cast<Site_index>(s));
  }
  std::sort(options.sites.begin(), options.sites.end());
  options.sites.erase(std::unique(options.sites.begin(), options.sites.end()), options.sites.end());
  const auto start = std::chrono::steady_clock::now();
  Octree_regions regions;
  Diagram vertices =
      octree_diagram(input.sites, Octree_options{command.diagram.threads, nullptr, Arithmetic::certified, &regions});
  const Diagram_topology topology = build_topology(input.sites, std::move(vertices), regions, {command.diagram.threads});
  validate_topology(input.sites, topology);
  const auto after_diagram = std::chrono::steady_clock::now();
  const Diagram_mesh mesh = mesh_diagram(input.sites, topology, options);
  const auto end = std::chrono::steady_clock::now();
  write_command_output(command.output, out, [&](std::ostream& o) {
    if (obj)
      write_mesh_obj(o, mesh);
    else
      write_mesh_ply(o, mesh, command.ascii);
  });
  if (command.quality) {
    const Mesh_quality q = mesh_quality(mesh);
    out << "measure minimum mean (over " << q.triangles << " face triangles)\n";
    static const char* names[5] = {"Q_amin", "Q_Ll", "Q_ALS", "Q_Rr", "Q_lr"};
    for (int k = 0; k < 5; ++k) {
      char line[128];
      std::snprintf(line, sizeof line, "%s %.6f %.6f\n", names[k], q.minimum[k], q.mean[k]);
      out << line;
    }
  }
  if (mesh.statistics.open_cells > 0)  // the mesh is written all the same: its closed cells are usable
    err << "apollonius3d: warning: " << mesh.statistics.open_cells
        << " cells are not closed (faces that could not be meshed; --stats has the counts)\n";
  if (command.stats) {
    const Mesh_statistics& s = mesh.statistics;
    err << "mesh count\npoints " << mesh.points.size() << "\ntriangles " << mesh.triangles.size() << "\nfaces_meshed "
        << s.faces_meshed << "\nedge_samples " << s.edge_samples << "\nopen_rims " << s.open_rims << "\nfaces_not_remeshed " << s.faces_not_remeshed << "\nremesh_abandoned " << s.remesh_abandoned << "\nopen_cells " << s.open_cells << "\nstep "
        << round_trip(mesh.step) << "\nmesh seconds\ndiagram " << std::chrono::duration<double>(after_diagram - start).count()
        << "\nsampling " << s.sampling_seconds << "\nfaces " << s.faces_seconds << "\ncut " << s.cut_seconds << "\ntotal "
        << std::chrono::duration<double>(end - start).count() << '\n';
  }
  return EXIT_OK;
}

}  // namespace

Command_run add_mesh_command(CLI::App& app) {
  auto command = std::make_shared<Mesh_command>();
  CLI::App* sub = app.add_subcommand(
      "mesh",
      "A triangle mesh of every face of the exact diagram, cut by a box, closed per cell by the box's walls\n"
      "(paper section 5.4): each face triangulated in its bisector plane (CGAL's Delaunay refinement and\n"
      "Lloyd iterations under the paper's density, eq. 37) and lifted onto its sheet; faces that share an\n"
      "edge share its samples. PLY (binary unless --ascii) or OBJ by OUT's extension. APPROXIMATE coordinates.");
  sub->add_option("INPUT", command->input, "the sites, as for 'vertices' (- for standard input)")->required();
  sub->add_option("-o,--output", command->output, "OUT.ply or OUT.obj, written atomically")->required()->type_name("OUT");
  command->step_option = sub->add_option("--step", command->step, "the sampling step (default: 2% of the box's diagonal)")
      ->check(finite_number)
      ->type_name("S");
  sub->add_option("--box", command->box,
                  "the box that cuts the faces (default: the sites' bounding box grown by their largest weight)")
      ->expected(6)
      ->check(finite_number)
      ->type_name("X0 Y0 Z0 X1 Y1 Z1");
  command->probe_option =
      sub->add_option("--probe", command->probe,
                      "cuts each face (i, j) where d_i <= P and closes each cell by its sphere of radius w_i + P "
                      "(as 'contacts'), instead of a box")
          ->check(finite_number)
          ->type_name("P");
  sub->add_option("--sites", command->sites, "only the cells of these sites (0-based), e.g. --sites 3,7,12")
      ->delimiter(',')
      ->type_name("I,J,...");
  sub->add_option("--lloyd", command->lloyd, "Lloyd iterations per face (0 for none)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  sub->add_flag("--quality", command->quality,
                "prints the five measures of the paper's Table 1, minimum and mean over the faces' triangles");
  sub->add_flag("--ascii", command->ascii, "PLY as text");
  sub->add_flag("--stats", command->stats, "counts and phase times on standard error");
  add_diagram_options(*sub, command->diagram);
  return [command](std::ostream& out, std::ostream& err) { return run(*command, out, err); };
}

}  // namespace apollonius

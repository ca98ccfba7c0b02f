#include "io/write_mesh.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <tuple>

#include "io/round_trip.h"

namespace apollonius {
namespace {

// The bytes of a value, least significant first, whatever the machine's order.
template <class T>
void put_little_endian(std::ostream& out, T value) {
  static_assert(sizeof(T) == 1 || sizeof(T) == 4 || sizeof(T) == 8);
  std::uint64_t bits = 0;
  if constexpr (sizeof(T) == 8) {
    std::memcpy(&bits, &value, 8);
  } else if constexpr (sizeof(T) == 4) {
    std::uint32_t word;
    std::memcpy(&word, &value, 4);
    bits = word;
  } else {
    std::uint8_t byte;
    std::memcpy(&byte, &value, 1);
    bits = byte;
  }
  char bytes[sizeof(T)];
  for (std::size_t k = 0; k < sizeof(T); ++k) bytes[k] = static_cast<char>((bits >> (8 * k)) & 0xffu);
  out.write(bytes, sizeof(T));
}

}  // namespace

void write_mesh_ply(std::ostream& out, const Diagram_mesh& mesh, bool ascii) {
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\n"
      << "comment apollonius3d mesh: faces (site_a < site_b) and box walls (site_a = -1 - wall, face_id = -1)\n"
      << "element vertex " << mesh.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.triangles.size()
      << "\nproperty list uchar int vertex_indices\nproperty int site_a\nproperty int site_b\nproperty int face_id\n"
      << "end_header\n";
  if (ascii) {
    for (const Point3& p : mesh.points) out << round_trip(p[0]) << ' ' << round_trip(p[1]) << ' ' << round_trip(p[2]) << '\n';
    for (const Mesh_triangle& t : mesh.triangles)
      out << "3 " << t.vertices[0] << ' ' << t.vertices[1] << ' ' << t.vertices[2] << ' ' << t.site_a << ' ' << t.site_b
          << ' ' << t.face_id << '\n';
    return;
  }
  for (const Point3& p : mesh.points)
    for (double x : p) put_little_endian(out, x);
  for (const Mesh_triangle& t : mesh.triangles) {
    put_little_endian(out, static_cast<std::uint8_t>(3));
    for (std::uint32_t v : t.vertices) put_little_endian(out, static_cast<std::int32_t>(v));
    put_little_endian(out, t.site_a);
    put_little_endian(out, t.site_b);
    put_little_endian(out, static_cast<std::int32_t>(t.face_id));
  }
}

void write_mesh_obj(std::ostream& out, const Diagram_mesh& mesh) {
  out << "# apollonius3d mesh: one group per face (face_ID_A_B) and per wall piece of a cell (wall_W_I)\n";
  for (const Point3& p : mesh.points)
    out << "v " << round_trip(p[0]) << ' ' << round_trip(p[1]) << ' ' << round_trip(p[2]) << '\n';
  // Groups in order of face id, then walls by wall and cell.
  std::map<std::tuple<int, std::int64_t, std::int32_t, std::int32_t>, std::vector<const Mesh_triangle*>> groups;
  for (const Mesh_triangle& t : mesh.triangles)
    groups[t.is_wall() ? std::make_tuple(1, std::int64_t(-1 - t.site_a), t.site_b, 0)
                       : std::make_tuple(0, t.face_id, t.site_a, t.site_b)]
        .push_back(&t);
  for (const auto& [key, list] : groups) {
    const auto& [kind, id, x, y] = key;
    if (kind == 0)
      out << "o face_" << id << '_' << x << '_' << y << '\n';
    else
      out << "o wall_" << id << '_' << x << '\n';
    for (const Mesh_triangle* t : list)
      out << "f " << t->vertices[0] + 1 << ' ' << t->vertices[1] + 1 << ' ' << t->vertices[2] + 1 << '\n';
  }
}

}  // namespace apollonius

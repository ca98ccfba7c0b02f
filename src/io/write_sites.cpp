#include "io/write_sites.h"

#include "io/round_trip.h"

namespace apollonius {

void write_sites_text(std::ostream& out, const std::vector<Site>& sites, const std::string& comment) {
  if (!comment.empty()) out << "# " << comment << '\n';
  for (const Site& s : sites)
    out << round_trip(s.x) << ' ' << round_trip(s.y) << ' ' << round_trip(s.z) << ' ' << round_trip(s.w) << '\n';
}

}  // namespace apollonius

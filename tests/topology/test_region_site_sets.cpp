// Region_site_sets groups the octree's region boxes by their site sets: every box in exactly one set, whose
// sites are the box's, distinct sets with distinct sites, numbered by first box, each list ascending. On
// random lists with many repeats (against a std::map of the sets) and on a real octree's regions.
#include <doctest/doctest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

#include "octree/octree_diagram.h"
#include "reference/site_generators.h"
#include "topology/region_site_sets.h"

using namespace apollonius;

namespace {

void check_grouping(const Octree_regions& regions) {
  const Region_site_sets sets(regions);
  std::map<std::vector<Site_index>, std::size_t> number_of;  // the expected numbering: by first box
  std::vector<std::size_t> set_of_box(regions.boxes.size());
  for (std::size_t b = 0; b < regions.boxes.size(); ++b) {
    const std::vector<Site_index> key(regions.boxes[b].sites.begin(), regions.boxes[b].sites.end());
    set_of_box[b] = number_of.emplace(key, number_of.size()).first->second;
  }
  REQUIRE(sets.size() == number_of.size());
  std::vector<int> seen(regions.boxes.size(), 0);
  for (std::size_t s = 0; s < sets.size(); ++s) {
    CAPTURE(s);
    const Region_site_sets::Boxes boxes = sets.boxes(s);
    REQUIRE(boxes.size() > 0);
    CHECK(std::is_sorted(boxes.begin(), boxes.end()));
    for (std::uint32_t b : boxes) {
      ++seen[b];
      CHECK(set_of_box[b] == s);
      CHECK(regions.boxes[b].sites == sets.sites(s));
    }
  }
  for (std::size_t b = 0; b < regions.boxes.size(); ++b) CHECK(seen[b] == 1);
}

}  // namespace

TEST_CASE("region site sets: random boxes with repeated sets") {
  for (std::uint32_t seed = 1; seed <= 200; ++seed) {
    CAPTURE(seed);
    std::mt19937 random(seed);
    const std::size_t site_count = 3 + random() % 12, box_count = random() % 3000;
    Octree_regions regions;
    for (std::size_t b = 0; b < box_count; ++b) {
      Octree_regions::Box box;
      for (Site_index s = 0; s < site_count; ++s)
        if (random() % 3 == 0) box.sites.push_back(s);
      regions.boxes.push_back(box);
    }
    check_grouping(regions);
  }
}

TEST_CASE("region site sets: an octree's regions") {
  for (const Site_family family : {Site_family::uniform, Site_family::lattice, Site_family::circle_mixed}) {
    const std::string name = name_of(family);
    CAPTURE(name);
    const std::vector<Site> sites = generate_sites(family, 150, 3);
    Octree_regions regions;
    Octree_options options;
    options.regions = &regions;
    options.octree_alone();  // circle-mixed passes the box budget: its boxes, not the lifted fallback's none
    octree_diagram(sites, options);
    REQUIRE(regions.boxes.size() > 100);
    check_grouping(regions);
    const Region_site_sets sets(regions);
    MESSAGE(name << ": " << regions.boxes.size() << " region boxes, " << sets.size() << " site sets");
  }
}

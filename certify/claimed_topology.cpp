#include "certify/claimed_topology.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

#include "io/input_error.h"
#include "io/json_input.h"
#include "io/text_input.h"

namespace apollonius {
namespace {

const char* singular(Topology_category category) {
  switch (category) {
    case Topology_category::bisectors: return "a bisector";
    case Topology_category::trisectors: return "a trisector";
    case Topology_category::quadrisectors: return "a quadrisector";
  }
  return "a set";
}

Claimed_set read_set(const Json_node& node, Topology_category category, std::size_t site_count, const std::string& name) {
  if (!node.value().is_array())
    throw Input_error(name, node.line(), std::string(singular(category)) + " must be an array of site indices, not " + node.kind());
  Claimed_set set{{}, node.line()};
  for (std::size_t k = 0; k < node.size(); ++k) {
    const Json_node site = node.element(k);
    const nlohmann::json& v = site.value();
    if (!v.is_number_integer() || v.get<std::int64_t>() < 0 ||
        v.get<std::uint64_t>() > std::numeric_limits<Site_index>::max())
      throw Input_error(name, site.line(), "not a site index: " + v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    const std::uint64_t index = v.get<std::uint64_t>();
    if (index >= site_count)
      throw Input_error(name, site.line(), "site index " + std::to_string(index) + " out of range (the input has " +
                                               std::to_string(site_count) + " sites)");
    set.sites.push_back(static_cast<Site_index>(index));
  }
  const std::size_t least = least_size(category);
  const bool exact_size = category == Topology_category::bisectors;
  if (set.sites.size() < least || (exact_size && set.sites.size() != least))
    throw Input_error(name, node.line(), std::string(singular(category)) + " has " + (exact_size ? "" : "at least ") +
                                             std::to_string(least) + " sites, found " + std::to_string(set.sites.size()));
  std::sort(set.sites.begin(), set.sites.end());
  if (const auto repeated = std::adjacent_find(set.sites.begin(), set.sites.end()); repeated != set.sites.end())
    throw Input_error(name, node.line(), "site index " + std::to_string(*repeated) + " listed twice");
  return set;
}

}  // namespace

const char* name_of(Topology_category category) {
  switch (category) {
    case Topology_category::bisectors: return "bisectors";
    case Topology_category::trisectors: return "trisectors";
    case Topology_category::quadrisectors: return "quadrisectors";
  }
  return "unknown";
}

Claimed_topology read_claimed_topology(const std::string& content, const std::string& name, std::size_t site_count) {
  if (starts_with_byte_order_mark(content))
    return read_claimed_topology(content.substr(byte_order_mark.size()), name, site_count);
  reject_binary_data(content, name);
  const Json_document parsed = parse_json(content, name);
  const Json_node document(parsed.value, parsed.lines);
  if (!document.value().is_object())
    throw Input_error(name, document.line(), std::string("expected a JSON object, found ") + document.kind());
  Claimed_topology topology;
  for (const Topology_category category : topology_categories) {
    const std::optional<Json_node> sets = document.member(name_of(category));
    if (!sets) continue;
    if (!sets->value().is_array())
      throw Input_error(name, sets->line(), std::string("\"") + name_of(category) + "\" must be an array, not " + sets->kind());
    Claimed_category& claimed = topology.categories[static_cast<std::size_t>(category)];
    claimed.present = true;
    for (std::size_t i = 0; i < sets->size(); ++i) claimed.sets.push_back(read_set(sets->element(i), category, site_count, name));
  }
  if (std::none_of(topology.categories.begin(), topology.categories.end(), [](const Claimed_category& c) { return c.present; }))
    throw Input_error(name, document.line(), "no \"bisectors\", \"trisectors\" or \"quadrisectors\" array");
  return topology;
}

}  // namespace apollonius

#include "certify/claimed_vertices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "io/input_error.h"
#include "io/json_input.h"
#include "io/text_input.h"

namespace apollonius {
namespace {

constexpr const char* kJsonFormatName = "apollonius3d-vertices";

// Sorts the sites of a claim, with its links, and checks the invariant of Claimed_vertex.
void check_sites(Claimed_vertex& claim, std::size_t site_count, const std::string& name, std::size_t line) {
  std::vector<Site_index>& sites = claim.sites;
  if (sites.size() < 4)
    throw Input_error(name, line, "a vertex needs 4 or more site indices, found " + std::to_string(sites.size()));
  for (const Site_index site : sites)
    if (site >= site_count)
      throw Input_error(name, line, "site index " + std::to_string(site) + " out of range (the input has " +
                                        std::to_string(site_count) + " sites)");
  if (claim.links) {  // Voronota's 4 sites: sort the (site, link) pairs
    std::array<std::pair<Site_index, long long>, 4> pairs;
    for (std::size_t i = 0; i < 4; ++i) pairs[i] = {sites[i], (*claim.links)[i]};
    std::sort(pairs.begin(), pairs.end());
    for (std::size_t i = 0; i < 4; ++i) std::tie(sites[i], (*claim.links)[i]) = pairs[i];
  } else {
    std::sort(sites.begin(), sites.end());
  }
  if (const auto repeated = std::adjacent_find(sites.begin(), sites.end()); repeated != sites.end())
    throw Input_error(name, line, "site index " + std::to_string(*repeated) + " listed twice");
}

Site_index parse_site_index(std::string_view field, const std::string& name, std::size_t line) {
  Site_index index = 0;
  if (!parse_integer(field, index)) throw Input_error(name, line, "not a site index: '" + std::string(field) + "'");
  return index;
}

// One line of text or Voronota output: index_count site indices, then x y z r.
// With links given (Voronota's --link), they are set before the sites are sorted.
Claimed_vertex parse_line(const std::vector<std::string_view>& fields, std::size_t index_count, std::size_t site_count,
                          const std::string& name, std::size_t line,
                          std::optional<std::array<long long, 4>> links = std::nullopt) {
  Claimed_vertex claim;
  claim.line = line;
  claim.links = links;
  for (std::size_t i = 0; i < index_count; ++i) claim.sites.push_back(parse_site_index(fields[i], name, line));
  for (std::size_t j = 0; j < 4; ++j) claim.point[j] = parse_number(fields[index_count + j], name, line, Infinity::allowed);
  check_sites(claim, site_count, name, line);
  return claim;
}

std::vector<Claimed_vertex> read_text(const std::vector<Text_line>& lines, std::size_t site_count, const std::string& name) {
  std::vector<Claimed_vertex> claims;
  for (const Text_line& line : lines) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (fields.size() < 8)
      throw Input_error(name, line.number, "expected 4 or more site indices, then x y z r; found " +
                                               std::to_string(fields.size()) + " fields");
    claims.push_back(parse_line(fields, fields.size() - 4, site_count, name, line.number));
  }
  return claims;
}

std::vector<Claimed_vertex> read_voronota(const std::vector<Text_line>& lines, std::size_t site_count,
                                          const std::string& name) {
  std::vector<Claimed_vertex> claims;
  for (const Text_line& line : lines) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    if (fields.size() != 8 && fields.size() != 12)
      throw Input_error(name, line.number, "expected 'q1 q2 q3 q4 x y z r', with --link 4 more integers; found " +
                                               std::to_string(fields.size()) + " fields");
    std::optional<std::array<long long, 4>> links;
    if (fields.size() == 12) {
      links.emplace();
      for (std::size_t i = 0; i < 4; ++i)
        if (!parse_integer(fields[8 + i], (*links)[i]) || (*links)[i] < -1)
          throw Input_error(name, line.number, "not a vertex link (an index or -1): '" + std::string(fields[8 + i]) + "'");
    }
    claims.push_back(parse_line(fields, 4, site_count, name, line.number, links));
  }
  // A link names a claim by its 0-based index among the data lines (Voronota writes no other lines).
  for (const Claimed_vertex& claim : claims)
    if (claim.links)
      for (const long long link : *claim.links)
        if (link >= 0 && static_cast<unsigned long long>(link) >= claims.size())
          throw Input_error(name, claim.line, "vertex link " + std::to_string(link) + " out of range (the list has " +
                                                  std::to_string(claims.size()) + " vertices)");
  return claims;
}

// A JSON number, or the string "inf" or "-inf" that our writer prints for an overflowing coordinate.
double json_coordinate(const Json_node& vertex, const char* key, const std::string& name) {
  const std::optional<Json_node> value = vertex.member(key);
  if (!value) throw Input_error(name, vertex.line(), std::string("vertex without \"") + key + "\"");
  const nlohmann::json& v = value->value();
  if (v.is_string() && (v == "inf" || v == "-inf"))
    return v == "inf" ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  if (!v.is_number())
    throw Input_error(name, value->line(), std::string("\"") + key + "\" must be a number, not " + value->kind());
  return v.get<double>();
}

// A site index: a JSON integer from 0 to the largest Site_index.
Site_index json_site_index(const Json_node& site, const std::string& name) {
  const nlohmann::json& v = site.value();
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::uint64_t>() > std::numeric_limits<Site_index>::max())
    throw Input_error(name, site.line(), "not a site index: " + v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  return static_cast<Site_index>(v.get<std::uint64_t>());
}

std::vector<Claimed_vertex> read_json(const std::string& content, std::size_t site_count, const std::string& name) {
  const Json_document parsed = parse_json(content, name);
  const Json_node document(parsed.value, parsed.lines);
  if (!document.value().is_object())
    throw Input_error(name, document.line(), std::string("expected a JSON object, found ") + document.kind());
  if (const std::optional<Json_node> format = document.member("format");
      format && format->value() != kJsonFormatName)
    throw Input_error(name, format->line(), std::string("\"format\" must be \"") + kJsonFormatName + "\"");
  if (const std::optional<Json_node> sites = document.member("sites")) {
    if (!sites->value().is_number_unsigned()) throw Input_error(name, sites->line(), "\"sites\" must be a site count");
    const std::uint64_t count = sites->value().get<std::uint64_t>();
    if (count != site_count)
      throw Input_error(name, sites->line(), "this vertex list is for " + std::to_string(count) +
                                                 " sites, the input has " + std::to_string(site_count));
  }
  const std::optional<Json_node> vertices = document.member("vertices");
  if (!vertices) throw Input_error(name, document.line(), "no \"vertices\" array");
  if (!vertices->value().is_array())
    throw Input_error(name, vertices->line(), std::string("\"vertices\" must be an array, not ") + vertices->kind());

  std::vector<Claimed_vertex> claims;
  for (std::size_t i = 0; i < vertices->size(); ++i) {
    const Json_node vertex = vertices->element(i);
    if (!vertex.value().is_object())
      throw Input_error(name, vertex.line(), std::string("a vertex must be an object, not ") + vertex.kind());
    Claimed_vertex claim;
    claim.line = vertex.line();
    const std::optional<Json_node> sites = vertex.member("sites");
    if (!sites || !sites->value().is_array()) throw Input_error(name, vertex.line(), "vertex without a \"sites\" array");
    for (std::size_t k = 0; k < sites->size(); ++k) claim.sites.push_back(json_site_index(sites->element(k), name));
    const char* const keys[4] = {"x", "y", "z", "r"};
    for (int j = 0; j < 4; ++j) claim.point[j] = json_coordinate(vertex, keys[j], name);
    check_sites(claim, site_count, name, vertex.line());
    claims.push_back(std::move(claim));
  }
  return claims;
}

}  // namespace

const char* name_of(Claim_format format) {
  switch (format) {
    case Claim_format::text: return "text";
    case Claim_format::json: return "json";
    case Claim_format::voronota: return "voronota";
    case Claim_format::topology: return "topology";
  }
  return "unknown";
}

std::optional<Claim_format> claim_format_from_name(const std::string& name) {
  for (const Claim_format format : {Claim_format::text, Claim_format::json, Claim_format::voronota, Claim_format::topology})
    if (name == name_of(format)) return format;
  return std::nullopt;
}

Claim_format detect_claim_format(const std::string& content) {
  const std::size_t start = starts_with_byte_order_mark(content) ? byte_order_mark.size() : 0;
  const std::size_t first = content.find_first_not_of(" \t\r\n\f\v", start);
  if (first != std::string::npos && content[first] == '{') {
    // Malformed JSON is json here; its reader names the line.
    try {
      const Json_document document = parse_json(std::string_view(content).substr(start), "");
      for (const char* key : {"bisectors", "trisectors", "quadrisectors"})
        if (document.value.is_object() && document.value.contains(key)) return Claim_format::topology;
    } catch (const Input_error&) {
    }
    return Claim_format::json;
  }
  for (const Text_line& line : split_lines(content)) {
    const std::vector<std::string_view> fields = data_fields(line.text);
    if (fields.empty()) continue;
    return fields.size() == 12 && !is_integer(fields[4]) ? Claim_format::voronota : Claim_format::text;
  }
  return Claim_format::text;
}

Claimed_vertex_list read_claimed_vertices(const std::string& content, const std::string& name,
                                          std::optional<Claim_format> format, std::size_t site_count) {
  if (starts_with_byte_order_mark(content))
    return read_claimed_vertices(content.substr(byte_order_mark.size()), name, format, site_count);
  reject_binary_data(content, name);
  Claimed_vertex_list list;
  list.format = format ? *format : detect_claim_format(content);
  switch (list.format) {
    case Claim_format::json: list.vertices = read_json(content, site_count, name); break;
    case Claim_format::voronota: list.vertices = read_voronota(split_lines(content), site_count, name); break;
    case Claim_format::text: list.vertices = read_text(split_lines(content), site_count, name); break;
    case Claim_format::topology: throw std::logic_error("read_claimed_vertices: a topology claim is no vertex list");
  }
  return list;
}

}  // namespace apollonius

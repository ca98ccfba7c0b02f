#include "claimed_vertices.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <istream>
#include <map>
#include <sstream>

#include "io/input_error.h"

namespace apollonius {
namespace {

using Quadruple_key = std::array<Site_index, 4>;

// Every 4-subset of a sorted tie set, sorted.
void for_each_quadruple(const std::vector<Site_index>& tie, const std::function<void(const Quadruple_key&)>& f) {
  const std::size_t k = tie.size();
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d) f({tie[a], tie[b], tie[c], tie[d]});
}

double max_abs_difference(const std::array<double, 4>& x, const std::array<double, 4>& y) {
  double m = 0;
  for (int j = 0; j < 4; ++j) m = std::max(m, std::fabs(x[j] - y[j]));
  return m;
}

}  // namespace

std::vector<Claimed_vertex> read_claimed_vertices(std::istream& in, const std::string& name) {
  std::vector<Claimed_vertex> claims;
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream fields(text);
    std::vector<std::string> tokens;
    for (std::string t; fields >> t;) tokens.push_back(t);
    if (tokens.empty()) continue;
    if (tokens.size() < 8)
      throw Input_error(name, line, "expected 4 or more site indices and x y z r, found " +
                                        std::to_string(tokens.size()) + " fields");
    Claimed_vertex claim;
    claim.line = line;
    for (std::size_t i = 0; i + 4 < tokens.size(); ++i) {
      Site_index index = 0;
      const auto [end, error] = std::from_chars(tokens[i].data(), tokens[i].data() + tokens[i].size(), index);
      if (error != std::errc() || end != tokens[i].data() + tokens[i].size())
        throw Input_error(name, line, "not a site index: '" + tokens[i] + "'");
      claim.sites.push_back(index);
    }
    for (int j = 0; j < 4; ++j) {
      const std::string& t = tokens[tokens.size() - 4 + j];
      const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), claim.point[j]);
      if (error != std::errc() || end != t.data() + t.size() || !std::isfinite(claim.point[j]))
        throw Input_error(name, line, "not a finite number: '" + t + "'");
    }
    std::sort(claim.sites.begin(), claim.sites.end());
    claims.push_back(std::move(claim));
  }
  return claims;
}

Vertex_list_matching match_claims(const Diagram& diagram, const std::vector<Claimed_vertex>& claims) {
  std::map<Quadruple_key, std::vector<std::size_t>> vertices_of_quadruple;
  for (std::size_t v = 0; v < diagram.vertices.size(); ++v)
    for_each_quadruple(diagram.vertices[v].tie_set, [&](const Quadruple_key& q) { vertices_of_quadruple[q].push_back(v); });

  Vertex_list_matching result;
  std::vector<bool> claimed(diagram.vertices.size(), false);
  for (std::size_t c = 0; c < claims.size(); ++c) {
    const Claimed_vertex& claim = claims[c];
    const Quadruple_key key = {claim.sites[0], claim.sites[1], claim.sites[2], claim.sites[3]};
    const auto found = vertices_of_quadruple.find(key);
    std::size_t best = diagram.vertices.size();
    double best_error = INFINITY;
    if (found != vertices_of_quadruple.end()) {
      for (std::size_t v : found->second) {
        const auto& tie = diagram.vertices[v].tie_set;
        if (!std::includes(tie.begin(), tie.end(), claim.sites.begin(), claim.sites.end())) continue;
        const double error = max_abs_difference(claim.point, diagram.vertices[v].rounded);
        if (error < best_error) best = v, best_error = error;
      }
    }
    if (best == diagram.vertices.size()) {
      result.unmatched_claims.push_back(c);
    } else {
      result.matches.push_back({c, best, best_error});
      claimed[best] = true;
    }
  }
  for (std::size_t v = 0; v < diagram.vertices.size(); ++v)
    if (!claimed[v]) result.vertices_without_claim.push_back(v);
  return result;
}

}  // namespace apollonius

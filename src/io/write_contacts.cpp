#include "io/write_contacts.h"

#include <algorithm>
#include <charconv>
#include <string>

#include "io/json_output.h"
#include "io/round_trip.h"

namespace apollonius {
namespace {

void append_line(std::string& text, Site_index a, Site_index b, double value) {
  char number[32];
  text.append(number, std::to_chars(number, number + sizeof number, a).ptr);
  text += ' ';
  text.append(number, std::to_chars(number, number + sizeof number, b).ptr);
  text += ' ';
  text.append(number, write_round_trip(number, value));
  text += '\n';
}

}  // namespace

void write_contacts_text(std::ostream& out, const Contact_measures& measures) {
  // Each site's SAS line (when it has one) comes before its contacts with higher sites: (i, i) < (i, j).
  std::string text;
  std::size_t next = 0;
  for (Site_index i = 0; i < measures.sas.size(); ++i) {
    if (measures.sas[i] > 0) append_line(text, i, i, measures.sas[i]);
    for (; next < measures.contacts.size() && measures.contacts[next].a == i; ++next)
      append_line(text, i, measures.contacts[next].b, measures.contacts[next].area);
    if (text.size() > (1u << 16)) {
      out << text;
      text.clear();
    }
  }
  out << text;
}

void write_contact_volumes_text(std::ostream& out, const Contact_measures& measures) {
  std::string text;
  char number[32];
  for (Site_index i = 0; i < measures.volume.size(); ++i) {
    if (!(measures.volume[i] > 0)) continue;
    text.append(number, std::to_chars(number, number + sizeof number, i).ptr);
    text += ' ';
    text.append(number, write_round_trip(number, measures.volume[i]));
    text += '\n';
  }
  out << text;
}

void write_contacts_json(std::ostream& out, const Contact_measures& measures, const Contact_options& options) {
  Json document{{"format", "apollonius3d-contacts"},
                {"version", 1},
                {"sites", measures.sas.size()},
                {"probe", options.probe},
                {"relative_tolerance", options.relative_tolerance},
                {"approximate", "areas and volumes are cubatures; each error is an estimate, not a bound"}};
  Json& contacts = document["contacts"] = Json::array();
  for (const Contact& c : measures.contacts)
    contacts.push_back({{"sites", {c.a, c.b}}, {"area", c.area}, {"error", c.error}});
  Json& cells = document["cells"] = Json::array();
  for (Site_index i = 0; i < measures.sas.size(); ++i)
    cells.push_back({{"site", i},
                     {"sas", measures.sas[i]},
                     {"sas_error", measures.sas_error[i]},
                     {"volume", measures.volume[i]},
                     {"volume_error", measures.volume_error[i]}});
  Json& hidden = document["hidden_sites"] = Json::array();
  for (const Hidden_site& h : measures.hidden)
    hidden.push_back({{"site", h.site}, {"hidden_by", h.hidden_by}, {"duplicate", h.duplicate}});
  write_json_document(out, document);
}

}  // namespace apollonius

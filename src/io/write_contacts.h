// The contacts command's outputs (SPEC section 8): text as Voronota's calculate-contacts (`i j area`, i < j,
// and `i i sas`, ascending), the volumes (`i volume`), and JSON with every estimated error.
#pragma once

#include <ostream>

#include "measure/contact_measures.h"

namespace apollonius {

void write_contacts_text(std::ostream& out, const Contact_measures& measures);
void write_contact_volumes_text(std::ostream& out, const Contact_measures& measures);
void write_contacts_json(std::ostream& out, const Contact_measures& measures, const Contact_options& options);

}  // namespace apollonius

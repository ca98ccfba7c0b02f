#include "predicates/sign.h"

namespace apollonius {

const char* to_string(Sign s) {
  switch (s) {
    case Sign::NEGATIVE: return "NEGATIVE";
    case Sign::ZERO: return "ZERO";
    case Sign::POSITIVE: return "POSITIVE";
  }
  return "?";
}

}  // namespace apollonius

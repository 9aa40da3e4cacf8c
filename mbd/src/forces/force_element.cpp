#include "seflex/mbd/forces/force_element.hpp"

namespace seflex::mbd {

void evaluate(const ForceElement& fe, const HingeValues& h, bool latched, HingeForceResult& out) {
  std::visit(
      [&](const auto& el) {
        using T = std::decay_t<decltype(el)>;
        if constexpr (std::is_same_v<T, HingeLock>) evaluate(el, h, latched, out);
        else evaluate(el, h, out);
      },
      fe);
}

HingeForceResult evaluate(const ForceElement& fe, const HingeValues& h, bool latched) {
  HingeForceResult r;
  evaluate(fe, h, latched, r);
  return r;
}

const char* kind_name(const ForceElement& fe) {
  static const char* names[] = {"spring", "lock", "cable", "damper"};
  return names[fe.index()];
}

}  // namespace seflex::mbd

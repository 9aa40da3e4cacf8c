#include "seflex/mbd/force_element.hpp"

namespace seflex::mbd {

HingeForceResult evaluate(const ForceElement& fe, const HingeValues& h, bool latched) {
  return std::visit(
      [&](const auto& el) -> HingeForceResult {
        using T = std::decay_t<decltype(el)>;
        if constexpr (std::is_same_v<T, HingeLock>) return evaluate(el, h, latched);
        else return evaluate(el, h);
      },
      fe);
}

const char* kind_name(const ForceElement& fe) {
  static const char* names[] = {"spring", "lock", "cable", "damper"};
  return names[fe.index()];
}

}  // namespace seflex::mbd

#pragma once
// Typed indices of the multibody model, so a node index cannot be passed where a hinge index is
// expected (docs/style.md item 5). An index is a position in the corresponding Model vector.
#include <compare>

namespace seflex::mbd {

template <class Tag>
struct Index {
  int value = -1;
  constexpr Index() = default;
  constexpr explicit Index(int v) : value(v) {}
  constexpr bool valid() const { return value >= 0; }
  friend constexpr auto operator<=>(const Index&, const Index&) = default;
};

using NodeIndex = Index<struct NodeTag>;
using HingeIndex = Index<struct HingeTag>;
using SuperelementIndex = Index<struct SuperelementTag>;
using FlexibleBodyIndex = Index<struct FlexibleBodyTag>;
using RigidBodyIndex = Index<struct RigidBodyTag>;
using ForceElementIndex = Index<struct ForceElementTag>;
using LoadIndex = Index<struct LoadTag>;

}  // namespace seflex::mbd

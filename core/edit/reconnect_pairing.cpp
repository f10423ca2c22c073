#include "core/edit/reconnect_pairing.h"

namespace tfd::core {

bool lemmaAllowsJoin(const ReconnectEndpoint& a, const ReconnectEndpoint& b) {
  return a.charge() != b.charge();
}

const char* endpointName(int index) {
  static const char* const names[] = {"A", "B", "C", "D"};
  return index >= 0 && index < 4 ? names[index] : "?";
}

ReconnectPairing pairEndpoints(std::span<const ReconnectEndpoint, 4> e) {
  ReconnectPairing p;
  for (int s = 0; s < 2; ++s) {
    if (!lemmaAllowsJoin(e[2 * s], e[2 * s + 1])) {
      p.problem =
          std::string("segment ") + std::to_string(s + 1) + "'s ends " + endpointName(2 * s) +
          " and " + endpointName(2 * s + 1) + " (" + toString(e[2 * s].pattern) + ", " +
          (e[2 * s].incoming ? "incoming" : "outgoing") + "; " + toString(e[2 * s + 1].pattern) +
          ", " + (e[2 * s + 1].incoming ? "incoming" : "outgoing") +
          ") contradict Lemma 6.1 (an end is misclassified, e.g. next to a transition "
          "point or where the curve runs across the eigenvector)";
      return p;
    }
  }
  // Theorem 6.2: A joins the end of the second segment with the other charge; B the other one.
  const int a = lemmaAllowsJoin(e[0], e[2]) ? 2 : 3;
  const int b = a == 2 ? 3 : 2;
  p.partner = {a, b, 0, 0};
  p.partner[a] = 0, p.partner[b] = 1;
  p.consistent = true;
  return p;
}

}  // namespace tfd::core

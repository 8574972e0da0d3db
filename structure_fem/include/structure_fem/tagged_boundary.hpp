#pragma once
// Tagged boundary facets (the T6 mesh's 3-node edges, the T10 mesh's 6-node faces): the facets
// carrying a tag and their node set, one implementation for both dimensions.
#include <algorithm>
#include <string>
#include <vector>

#include "fsi/core/error.hpp"

namespace fsi::fem {

/// The facets carrying `tag`. Throws InputError "`source`: no boundary `what` is tagged ..." if
/// there are none.
template <class Facet>
std::vector<Facet> facets_with_tag(const std::vector<Facet>& facets, const std::string& tag,
                                   const std::string& source, const char* what) {
  std::vector<Facet> out;
  for (const auto& f : facets)
    if (f.tag == tag) out.push_back(f);
  if (out.empty())
    throw InputError(source + ": no boundary " + what + " is tagged \"" + tag + "\"");
  return out;
}

/// Sorted, unique nodes of the facets carrying `tag` (throws like facets_with_tag).
template <class Facet>
std::vector<int> facet_node_set(const std::vector<Facet>& facets, const std::string& tag,
                                const std::string& source, const char* what) {
  std::vector<int> nodes;
  for (const auto& f : facets_with_tag(facets, tag, source, what))
    nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

} // namespace fsi::fem

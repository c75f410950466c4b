#include "support/permutations.hpp"

#include <numeric>
#include <utility>

namespace dcel::props {

rc::Gen<std::vector<Index>> permutations(std::size_t n) {
    // At RapidCheck's nominal size inRange spans its whole range: without the
    // resize, small sizes would draw only short swaps.
    return rc::gen::resize(rc::kNominalSize, rc::gen::exec([n] {
                               std::vector<Index> p(n);
                               std::iota(p.begin(), p.end(), Index{0});
                               for (std::size_t i = 0; i + 1 < n; ++i) {
                                   const auto d = *rc::gen::inRange<std::size_t>(0, n - i);
                                   std::swap(p[i], p[i + d]);
                               }
                               return p;
                           }));
}

// The rotations and steps below are resized like the permutations: drawn
// over their whole range at every size.
rc::Gen<check::FacesAnswer> rewordings(const check::FacesAnswer& a) {
    return rc::gen::resize(rc::kNominalSize, rc::gen::exec([a] {
                               std::vector<std::size_t> turns(a.size(), 0);
                               for (std::size_t k = 0; k < a.size(); ++k) {
                                   if (!a[k].empty()) turns[k] = *rc::gen::inRange<std::size_t>(0, a[k].size());
                               }
                               return test_support::shuffled(a, *permutations(a.size()), turns);
                           }));
}

rc::Gen<DcelDump> renumberings(const DcelDump& d) {
    return rc::gen::resize(rc::kNominalSize, rc::gen::exec([d] {
                               test_support::DumpRenumbering r;
                               r.half_edges = *permutations(d.half_edges.size());
                               r.faces = *permutations(d.faces.size());
                               for (const FaceDump& f : d.faces) {
                                   std::vector<unsigned>& steps = r.steps.emplace_back();
                                   const std::size_t records = f.inner.size() + (f.outer.is_null() ? 0 : 1);
                                   for (std::size_t k = 0; k < records; ++k)
                                       steps.push_back(*rc::gen::inRange<unsigned>(0, 4));
                                   r.inner_order.push_back(*permutations(f.inner.size()));
                                   r.isolated_order.push_back(*permutations(f.isolated.size()));
                               }
                               return test_support::renumbered(d, r);
                           }));
}

}  // namespace dcel::props

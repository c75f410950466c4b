// compare_faces: an answer in the faces form against the reference cycles.
#include "dcel/check/collector.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/cycles.hpp"

namespace dcel::check {

CycleList CycleList::from(const FacesAnswer& faces) {
    CycleList list;
    list.begin.reserve(faces.size() + 1);
    for (const std::vector<Index>& cycle : faces) {
        list.ids.insert(list.ids.end(), cycle.begin(), cycle.end());
        list.end_cycle();
    }
    return list;
}

Report compare_faces(const Dcel& reference, const FacesAnswer& answer) {
    detail::Collector out;
    const detail::Reference ref(reference);
    const CycleList list = CycleList::from(answer);
    const detail::AnswerCycles cycles{&list, {}};
    (void)detail::match_cycles(ref, cycles, out);
    return std::move(out).finish();
}

}  // namespace dcel::check

// compare_faces: an answer in the faces form against the reference cycles.
#include "dcel/check/collector.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/cycles.hpp"

namespace dcel::check {

Report compare_faces(const Dcel& reference, const FacesAnswer& answer) {
    detail::Collector out;
    const detail::Reference ref(reference);
    const detail::AnswerCycles cycles{&answer, {}};
    (void)detail::match_cycles(ref, cycles, out);
    return std::move(out).finish();
}

}  // namespace dcel::check

// DcelObject, the C++ side of dcel.Dcel: a built DCEL shared with the numpy
// views of its arrays. Each view keeps the state it views alive, and an edit
// made while views exist first copies the state (copy on write): a view never
// changes and never dangles.
#pragma once

#include <memory>

#include "binding.hpp"
#include "dcel/dcel.hpp"
#include "dcel/point_locator.hpp"

namespace dcel::python {

class DcelObject {
public:
    explicit DcelObject(Dcel d) : state_(std::make_shared<Dcel>(std::move(d))) {}

    // The state, for the caller to hold for the whole of a call that reads
    // it: Python code may run in the middle of such a call (an argument's
    // __index__, a value type's constructor, a finaliser the collector runs
    // on an allocation, another thread while the GIL is released) and edit
    // this Dcel. Held, the state is copied by that edit (copy on write,
    // below) rather than changed or freed under the call.
    [[nodiscard]] std::shared_ptr<const Dcel> get() const { return state_; }

    // The DCEL an edit may change: copied first while numpy views of this
    // state or calls in progress hold it (they hold the other references).
    // Nothing may hold get() across this call, which would force the copy.
    Dcel& for_edit() {
        if (state_.use_count() > 1) state_ = std::make_shared<Dcel>(*state_);
        locator_.reset();  // a snapshot of the old geometry
        return *state_;
    }

    // Built on the first locate() after build or the last edit. Shared for
    // the same reason as get(): an edit drops this object's reference, not
    // the locator a call that released the GIL is using.
    std::shared_ptr<const PointLocator> locator() {
        if (!locator_) locator_ = std::make_shared<const PointLocator>(*state_);
        return locator_;
    }

    // A read-only array of `count` elements of T (rows of `columns` when
    // columns > 0) at `data`, which lies inside `state` (this object's, as
    // get() gave it): the array keeps that state alive.
    template <class T>
    [[nodiscard]] static py::array view(const std::shared_ptr<const Dcel>& state, const void* data, std::size_t count,
                                        py::ssize_t columns = 0) {
        auto* keep = new std::shared_ptr<const Dcel>(state);
        const py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<const Dcel>*>(p); });
        const auto n = static_cast<py::ssize_t>(count);
        const auto size = static_cast<py::ssize_t>(sizeof(T));
        py::array a = columns > 0 ? py::array_t<T>({n, columns}, {columns * size, size}, static_cast<const T*>(data), base)
                                  : py::array_t<T>({n}, {size}, static_cast<const T*>(data), base);
        a.attr("setflags")(py::arg("write") = false);
        return a;
    }

private:
    std::shared_ptr<Dcel> state_;
    std::shared_ptr<const PointLocator> locator_;
};

}  // namespace dcel::python

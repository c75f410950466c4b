// User data per vertex, edge or face that follows the edits.
//
//   dcel::FaceData<std::string> names(d, "");   // one value per face, all ""
//   names[dcel::FaceId(1)] = "West";
//   names.follow(dcel::add_edge(d, u, v));       // after every edit
//
// ElementData<Id, T> can only be indexed by its own id type. It is a plain
// array kept in step with the DCEL by follow(Change), which replays what the
// edit did to the ids (change.hpp):
//  - an added element gets a copy of the value of the element it was split
//    off (`added_from`): both parts of a split face keep the country's name,
//    both halves of a split edge keep the edge's value; an element with no
//    origin (a new vertex, a new edge) gets the default value;
//  - a removed element's value is dropped, except that when it was merged
//    into a survivor (two faces into one across a removed edge, two collinear
//    edges into one) the merge function runs first: by default the survivor
//    keeps its own value; pass one to combine, e.g. sum areas or join names;
//  - the element moved into a freed id takes its value along.
// follow() checks that the change fits (its ids match this array's size) and
// throws std::logic_error otherwise: a missed or repeated follow() shows up at
// the next edit instead of silently shifting values. O(1) per edit, plus the
// merge function and one move of T.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dcel/change.hpp"
#include "dcel/dcel.hpp"

namespace dcel {

template <class Id>
[[nodiscard]] std::size_t element_count(const Dcel& d) {
    if constexpr (std::is_same_v<Id, VertexId>) {
        return d.num_vertices();
    } else if constexpr (std::is_same_v<Id, EdgeId>) {
        return d.num_edges();
    } else {
        static_assert(std::is_same_v<Id, FaceId>, "user data is per vertex, edge or face");
        return d.num_faces();
    }
}

template <class Id, class T>
class ElementData {
    static_assert(!std::is_same_v<T, bool>, "std::vector<bool> has no references to elements: use char or an enum");

public:
    // merge(kept, absorbed): update the survivor's value when `absorbed` merges into it.
    using Merge = std::function<void(T& kept, T&& absorbed)>;

    ElementData() = default;
    // One value per element of d, each a copy of `initial`, which is also the
    // value of elements added later without an origin.
    explicit ElementData(const Dcel& d, T initial = T{}, Merge merge = {})
        : values_(element_count<Id>(d), initial), initial_(std::move(initial)), merge_(std::move(merge)) {}

    [[nodiscard]] T& operator[](Id id) { return values_[id.index()]; }
    [[nodiscard]] const T& operator[](Id id) const { return values_[id.index()]; }
    [[nodiscard]] T& at(Id id) { return values_.at(id.index()); }
    [[nodiscard]] const T& at(Id id) const { return values_.at(id.index()); }
    [[nodiscard]] std::size_t size() const { return values_.size(); }
    // Has one value per element of d (a cheap check that no follow() was missed).
    [[nodiscard]] bool in_step(const Dcel& d) const { return values_.size() == element_count<Id>(d); }

    // Replays one edit's change; see the rules at the top of this file.
    void follow(const Change& change) {
        const IdChange<Id>& c = change.of<Id>();
        if (!c.added.is_null()) {
            if (c.added.index() != values_.size()) out_of_step("adds " + c.added.str());
            if (!c.added_from.is_null() && c.added_from.index() >= values_.size()) {
                out_of_step("copies " + c.added_from.str());
            }
            values_.push_back(c.added_from.is_null() ? initial_ : values_[c.added_from.index()]);
        }
        if (!c.removed.is_null()) {
            const Id last = values_.empty() ? Id() : Id(static_cast<Index>(values_.size() - 1));
            if (last.is_null() || c.removed.index() > last.index() ||
                (c.moved.is_null() ? c.removed != last : c.moved != last)) {
                out_of_step("removes " + c.removed.str() + (c.moved.is_null() ? "" : " and moves " + c.moved.str()));
            }
            if (!c.merged_into.is_null() && merge_) {
                merge_(values_[c.merged_into.index()], std::move(values_[c.removed.index()]));
            }
            if (!c.moved.is_null()) values_[c.removed.index()] = std::move(values_.back());
            values_.pop_back();
        }
    }

private:
    [[noreturn]] void out_of_step(const std::string& what) const {
        throw std::logic_error("user data out of step with the DCEL: it holds " + std::to_string(values_.size()) +
                               " values but the edit " + what + "; call follow() once after every edit");
    }

    std::vector<T> values_;
    T initial_{};
    Merge merge_;
};

template <class T>
using VertexData = ElementData<VertexId, T>;
template <class T>
using EdgeData = ElementData<EdgeId, T>;
template <class T>
using FaceData = ElementData<FaceId, T>;

}  // namespace dcel

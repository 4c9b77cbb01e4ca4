#pragma once
// The distances' best-first order over node pairs: a min-heap by the least gap below a pair
// (ties by the pair's indices), kept in the query scratch. The least child of the pair in hand,
// when it comes before every pair on the heap, is handed back next without a trip through the
// heap: the same pairs in the same order as a push and a pop, at a fraction of their cost (the
// heap's sift was the largest part of the spheres distance's time on env/rob).
#include "query/scratch.hpp"
#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace spt::detail {

template <class Gap> class BestFirst {
public:
    using Bound = ScratchBuffers::GapBoundOf<Gap>;

    /// An empty order over `heap` (the scratch's room, cleared).
    explicit BestFirst(std::vector<Bound>& heap) : heap_(heap) { heap_.clear(); }

    /// Adds pair (a, b) whose contents lie at least `gap` apart (model units).
    void push(Gap gap, uint32_t a, uint32_t b) {
        heap_.push_back({gap, a, b});
        std::push_heap(heap_.begin(), heap_.end(), std::greater<Bound>());
    }

    /// Adds the `n` (0 to 2) children of the pair just taken; the least is carried when it
    /// would be the next taken anyway.
    void push_children(Bound* kids, int n) {
        if (n == 2 && kids[0] > kids[1]) std::swap(kids[0], kids[1]);
        if (n == 2) push(kids[1].gap, kids[1].a, kids[1].b);
        if (n == 0) return;
        if (heap_.empty() || heap_.front() > kids[0])
            carried_ = kids[0], have_carried_ = true;
        else
            push(kids[0].gap, kids[0].a, kids[0].b);
    }

    /// Takes the pair of least gap into `top`; false when none is left.
    bool take(Bound& top) {
        if (have_carried_) {
            top = carried_, have_carried_ = false;
            return true;
        }
        if (heap_.empty()) return false;
        top = heap_.front();
        const Bound last = heap_.back();
        heap_.pop_back();
        const size_t n = heap_.size();
        if (n == 0) return true;
        // As std::pop_heap does: the hole at the root sinks to a leaf along the lesser child,
        // then `last` rises from there. The lesser child is chosen without a branch: which one it
        // is, is a coin toss to a predictor (cachegrind: half the sphere distance's mispredicts).
        size_t hole = 0;
        for (size_t child = 1; child < n; child = 2 * hole + 1) {
            if (child + 1 < n) child += heap_[child] > heap_[child + 1];
            heap_[hole] = heap_[child];
            hole = child;
        }
        while (hole > 0) {
            const size_t parent = (hole - 1) / 2;
            if (!(heap_[parent] > last)) break;
            heap_[hole] = heap_[parent];
            hole = parent;
        }
        heap_[hole] = last;
        return true;
    }

private:
    std::vector<Bound>& heap_;
    Bound carried_{};
    bool have_carried_ = false;
};

} // namespace spt::detail

#pragma once
// A split chosen by someone other than the builder's strategy (the build from motion): the
// builder asks it first at every node it would split, and builds as usual where it declines.
#include "spt/sampling_tree.hpp"
#include "spt/tree_builder.hpp"
#include <cstdint>
#include <vector>

namespace spt::detail {

class SplitChooser {
public:
    virtual ~SplitChooser() = default;
    enum class Answer {
        Split,    // left[i] says whether members[i] goes to the left child
        Builder,  // the builder's strategy splits this node
        NotBelow, // ... and every node below it, without asking again
    };
    // The node's samples are members[0..n). Called from several threads at once on disjoint nodes.
    virtual Answer choose(const uint32_t* members, size_t n, NodeId id, std::vector<uint8_t>& left) const = 0;
};

// build_tree over `members` (sorted sample indices) with `chooser` asked first (may be null),
// ids from 1, at most max_depth deep.
SamplingTree build_over(std::string name, const SampleSet& samples, const std::vector<uint32_t>& members,
                        const BuildOptions& options, int max_depth, const SplitChooser* chooser);

// SamplingTree::build_subtree with `chooser` asked first.
struct TreeGraft {
    static EditResult build_subtree(SamplingTree& tree, NodeId id, const SampleSet& samples, const BuildOptions& options,
                                    const SplitChooser* chooser);
};

} // namespace spt::detail

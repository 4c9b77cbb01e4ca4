// Feet-first tree for the walking figure: one selection split at the root, median splits below.
#include "walk_tree.hpp"
#include "spt/error.hpp"
#include <algorithm>

namespace spt::scenegen {
namespace {

// Median split along the longest axis of the node's samples, recursively, leaves of <= 8.
void split_down(SamplingTree& tree, NodeId id, const SampleSet& s, const std::vector<Eigen::Vector3d>& at) {
    const TreeNode* node = tree.find(id);
    if (!node || node->samples.size() <= 8) return;
    std::vector<uint32_t> idx = node->samples;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (uint32_t i : idx) lo = lo.cwiseMin(at[i]), hi = hi.cwiseMax(at[i]);
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const auto mid = idx.begin() + long(idx.size() / 2);
    std::nth_element(idx.begin(), mid, idx.end(), [&](uint32_t a, uint32_t b) {
        const double pa = at[a][axis], pb = at[b][axis];
        return pa != pb ? pa < pb : a < b;
    });
    std::vector<uint32_t> left(idx.begin(), mid);
    std::sort(left.begin(), left.end());
    if (!tree.split(id, left, s)) return;
    split_down(tree, left_child(id), s, at);
    split_down(tree, right_child(id), s, at);
}

} // namespace

void add_feet_first_tree(SptDocument& doc, const std::string& name, double foot_height,
                         const std::vector<Eigen::Vector3d>& posed) {
    const SampleSet& s = doc.samples;
    std::vector<Eigen::Vector3d> at = posed;
    if (at.empty())
        for (uint32_t i = 0; i < s.size(); ++i) at.push_back(s.position(i));
    if (at.size() != s.size()) throw Error(ErrorKind::Usage, "feet-first tree: a pose for another sample set");
    double lowest = 1e300;
    for (uint32_t i = 0; i < s.size(); ++i) lowest = std::min(lowest, at[i].y());
    std::vector<uint32_t> feet;
    for (uint32_t i = 0; i < s.size(); ++i)
        if (at[i].y() < lowest + foot_height) feet.push_back(i);
    SamplingTree tree(name, uint32_t(s.size()));
    if (!tree.split(root_id(), feet, s)) throw Error(ErrorKind::BadInput, "feet selection did not split the figure");
    split_down(tree, left_child(root_id()), s, at);
    split_down(tree, right_child(root_id()), s, at);
    doc.trees.push_back(std::move(tree));
    const std::string problem = doc.validate();
    if (!problem.empty()) throw Error(ErrorKind::BadInput, "walk tree: " + problem);
}

} // namespace spt::scenegen

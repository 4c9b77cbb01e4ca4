// The paper's node ids: children and parent by shifting, depth by bit length.
#include "spt/node_id.hpp"
#include <gtest/gtest.h>

using namespace spt;

TEST(NodeId, ChildrenAndParentByShifting) {
    EXPECT_EQ(left_child(1), 2u);
    EXPECT_EQ(right_child(1), 3u);
    EXPECT_EQ(parent_of(2), 1u);
    EXPECT_EQ(parent_of(3), 1u);
    EXPECT_EQ(parent_of(1), 0u);
    EXPECT_TRUE(is_left_child(6));
    EXPECT_FALSE(is_left_child(7));
}

TEST(NodeId, DepthIsBitLengthMinusOne) {
    EXPECT_EQ(node_depth(1), 0);
    EXPECT_EQ(node_depth(2), 1);
    EXPECT_EQ(node_depth(3), 1);
    EXPECT_EQ(node_depth(NodeId(1) << kMaxNodeDepth), kMaxNodeDepth);
}

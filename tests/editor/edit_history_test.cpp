// A seeded script of 500+ random edits through the window's undo stack: undoing all of
// them restores the original file byte for byte, redoing all gives the final file.
#include "editor_support.hpp"
#include "spt/selection.hpp"
#include <QUndoStack>
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using namespace spt::test;

namespace {

// A random node of the edited tree matching `want` (active or inner), or 0.
NodeId pick_node(const editor::EditorDocument& d, std::mt19937& rng, bool active) {
    std::vector<NodeId> ids;
    for (const TreeNode* n : d.tree().nodes())
        if (n->active == active) ids.push_back(n->id);
    if (ids.empty()) return 0;
    return ids[std::uniform_int_distribution<size_t>(0, ids.size() - 1)(rng)];
}

} // namespace

TEST(EditHistory, FiveHundredRandomEditsUndoToTheOriginalBytesAndRedoToTheFinal) {
    TempDir dir("editor-history");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    editor::EditorDocument& d = w.document();
    const std::vector<uint8_t> original = d.encode();
    std::mt19937 rng(1201);
    int made = 0, refused = 0;
    std::vector<int> kinds(8, 0);
    while (made < 520) {
        const int kind = std::uniform_int_distribution<int>(0, 99)(rng);
        bool ok = false;
        int k = 0;
        if (kind < 40) { // split an active node by a random part of its samples
            k = 0;
            const NodeId id = pick_node(d, rng, true);
            if (id == 0) continue;
            d.set_current(id);
            std::vector<uint32_t> sel;
            for (uint32_t s : samples_below(d.tree(), id))
                if (std::bernoulli_distribution(0.4)(rng)) sel.push_back(s);
            d.set_selection(sel);
            ok = w.split();
        } else if (kind < 55) { // merge an inner node
            k = 1;
            const NodeId id = pick_node(d, rng, false);
            if (id == 0) continue;
            d.set_current(id);
            ok = w.merge();
        } else if (kind < 70) { // radius of an active node
            k = 2;
            d.set_current(pick_node(d, rng, true));
            ok = w.set_radius(std::uniform_real_distribution<float>(0.01f, 0.2f)(rng));
        } else if (kind < 78) { // automatic subtree
            k = 3;
            d.set_current(pick_node(d, rng, true));
            ok = w.build_subtree();
        } else if (kind < 84) {
            k = 4;
            ok = w.add_tree();
        } else if (kind < 89) {
            k = 5;
            ok = w.rename_tree(QString("tree %1").arg(made));
        } else if (kind < 94) {
            k = 6;
            ok = w.duplicate_tree();
        } else {
            k = 7;
            ok = w.delete_tree();
        }
        // Switch trees now and then (not an edit: it changes no byte).
        if (kind % 7 == 0) d.set_tree_index(int(rng() % d.document().trees.size()));
        if (ok) {
            ++made, ++kinds[size_t(k)];
            if (made % 50 == 0) {
                ASSERT_EQ(d.document().validate(), "") << "after edit " << made;
            }
        } else {
            ++refused;
        }
    }
    for (size_t k = 0; k < kinds.size(); ++k) EXPECT_GT(kinds[k], 0) << "edit kind " << k << " never made";
    ASSERT_EQ(w.undo_stack().count(), made);
    const std::vector<uint8_t> final_bytes = d.encode();
    ASSERT_NE(final_bytes, original);
    while (w.undo_stack().canUndo()) w.undo_stack().undo();
    EXPECT_EQ(d.encode(), original);
    while (w.undo_stack().canRedo()) w.undo_stack().redo();
    EXPECT_EQ(d.encode(), final_bytes);
    // Round trip through a file as well: what is saved is what was edited.
    ASSERT_TRUE(w.save_to(QString::fromStdString(dir.file("final.spt"))));
    EXPECT_EQ(encode_spt(load_spt(dir.file("final.spt"))), final_bytes);
    std::cout << made << " edits (" << refused << " refused with a reason)\n";
}

// A seeded script of 500+ random edits through the window's undo stack: undoing all of
// them restores the original file byte for byte, redoing all gives the final file.
#include "editor_support.hpp"
#include "spt/selection.hpp"
#include <QAction>
#include <QTest>
#include <QUndoStack>
#include <map>
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

TEST(EditHistory, CtrlZUndoesAndCtrlShiftZRedoesFromTheKeyboard) {
    // Redo's keys were Ctrl+Shift+Z and the platform's redo keys, which on X11 hold Ctrl+Shift+Z
    // again: a sequence given twice is an ambiguous shortcut, and Qt never fired it.
    TempDir dir("edit-history-keys");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    editor::ViewWidget* view = w->grid().view(1);
    view->setFocus();
    // Half the root's samples by a mouse rectangle over the left half of the front view, then S.
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseMove(view, QPoint(view->width() / 2, view->height() - 2));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, QPoint(view->width() / 2, view->height() - 2));
    ASSERT_FALSE(w->document().selection().empty());
    QTest::keyClick(view, Qt::Key_S);
    ASSERT_EQ(w->undo_stack().count(), 1) << w->last_message().toStdString();
    const size_t nodes = w->document().tree().node_count();
    QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(w->undo_stack().index(), 0);
    EXPECT_EQ(w->document().tree().node_count(), 1u);
    QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(w->undo_stack().index(), 1);
    EXPECT_EQ(w->document().tree().node_count(), nodes);
}

TEST(EditHistory, NoTwoActionsOfTheWindowShareAKey) {
    // Any key bound twice is ambiguous, and neither binding fires.
    TempDir dir("edit-history-shortcuts");
    editor::MainWindow w(test_start(dir));
    std::map<QString, QString> owner;
    for (const QAction* a : w.findChildren<QAction*>())
        for (const QKeySequence& k : a->shortcuts()) {
            const QString key = k.toString(QKeySequence::PortableText);
            const auto [it, fresh] = owner.emplace(key, a->text());
            EXPECT_TRUE(fresh) << key.toStdString() << " is bound by '" << it->second.toStdString() << "' and by '"
                               << a->text().toStdString() << "'";
        }
    EXPECT_TRUE(owner.count("Ctrl+Shift+Z")) << "redo";
    EXPECT_TRUE(owner.count("Ctrl+Z")) << "undo";
}

// The rest of a session's file handling and settings: drag and drop, Open Recent, Revert
// (asking first), and preferences that apply at once and persist.
#include "editor_support.hpp"
#include "meshgen.hpp"
#include "spt/recipe.hpp"
#include "spt/spt_file.hpp"
#include "cost_panel.hpp"
#include "tree_panel.hpp"
#include "radius_box.hpp"
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoView>
#include <QUrl>
#include <filesystem>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

// Presses `button` in the next message box that shows up (a modal question of the window).
void answer_next_question(QMessageBox::StandardButton button) {
    QTimer::singleShot(50, [button] {
        for (int i = 0; i < 100; ++i) {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                box->button(button)->click();
                return;
            }
            QTest::qWait(20);
        }
    });
}

QAction* menu_action(QMenu* menu, const QString& text) {
    for (QAction* a : menu->actions())
        if (a->text() == text) return a;
    return nullptr;
}

QMenu* file_menu(editor::MainWindow& w) {
    for (QAction* a : w.menuBar()->actions())
        if (a->text() == "&File") return a->menu();
    return nullptr;
}

} // namespace

TEST(EditorSession, DroppingAFileOnTheWindowOpensIt) {
    TempDir dir("editor-drop");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    // Another document: the torus saved with one more tree.
    ASSERT_TRUE(w->add_tree("walking"));
    const QString other = QString::fromStdString(dir.file("other.spt"));
    ASSERT_TRUE(w->save_to(other));
    w->undo_stack().undo();
    ASSERT_TRUE(w->save_to(QString::fromStdString(dir.file("torus.spt"))));
    const size_t before = w->document().document().trees.size();

    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(other)});
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.get(), &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.get(), &drop);
    ASSERT_TRUE(wait_ready(*w));
    EXPECT_EQ(w->document().document().trees.size(), before + 1);
    EXPECT_NE(w->document().document().tree("walking"), nullptr);
    EXPECT_TRUE(w->windowTitle().startsWith("other.spt")) << w->windowTitle().toStdString();
}

TEST(EditorSession, OpenRecentListsOpenedFilesNewestFirstAndReopensThem) {
    TempDir dir("editor-recent");
    std::string error;
    const EditorFiles files = write_editor_files(dir);
    const auto w = open_editor(dir, files.spt, &error);
    ASSERT_TRUE(w) << error;
    const QString second = QString::fromStdString(dir.file("second.spt"));
    std::filesystem::copy_file(files.spt.toStdString(), second.toStdString());
    w->open_file(second);
    ASSERT_TRUE(wait_ready(*w));
    const QStringList recent = w->recent_files();
    ASSERT_GE(recent.size(), 2);
    EXPECT_EQ(recent[0], QFileInfo(second).absoluteFilePath());
    EXPECT_EQ(recent[1], QFileInfo(files.spt).absoluteFilePath());
    QMenu* file = file_menu(*w);
    ASSERT_TRUE(file);
    QAction* open_recent = menu_action(file, "Open &Recent");
    ASSERT_TRUE(open_recent && open_recent->menu());
    QAction* first_file = menu_action(open_recent->menu(), QFileInfo(files.spt).absoluteFilePath());
    ASSERT_TRUE(first_file) << "the first file is not in Open Recent";
    first_file->trigger();
    ASSERT_TRUE(wait_ready(*w));
    EXPECT_TRUE(w->windowTitle().startsWith("torus.spt")) << w->windowTitle().toStdString();
    EXPECT_EQ(w->recent_files()[0], QFileInfo(files.spt).absoluteFilePath());
}

TEST(EditorSession, RevertAsksThenReloadsTheFileAndKeepingTheChangesKeepsThem) {
    TempDir dir("editor-revert");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    const size_t trees = w->document().document().trees.size();
    ASSERT_TRUE(w->add_tree("scratch"));
    ASSERT_TRUE(w->modified());
    // Cancel keeps the edit.
    answer_next_question(QMessageBox::Cancel);
    EXPECT_FALSE(w->revert());
    EXPECT_EQ(w->document().document().trees.size(), trees + 1);
    EXPECT_TRUE(w->modified());
    // Discard reloads the file without asking to save.
    answer_next_question(QMessageBox::Discard);
    EXPECT_TRUE(w->revert());
    ASSERT_TRUE(wait_ready(*w));
    EXPECT_EQ(w->document().document().trees.size(), trees);
    EXPECT_FALSE(w->modified());
    EXPECT_EQ(w->undo_stack().count(), 0);
}

TEST(EditorSession, PreferencesApplyAtOnceAndPersist) {
    TempDir dir("editor-preferences");
    std::string error;
    {
        const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
        ASSERT_TRUE(w) << error;
        w->show_preferences();
        auto* dialog = w->findChild<editor::PreferencesDialog*>();
        ASSERT_TRUE(dialog) << "no preferences dialog";
        ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
        dialog->findChild<QSpinBox*>("autosave_seconds")->setValue(7);
        dialog->findChild<QCheckBox*>("swap_modifiers")->setChecked(true);
        dialog->findChild<QCheckBox*>("visible_only")->setChecked(true);
        dialog->findChild<QComboBox*>("color_by")->setCurrentIndex(1);
        dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        EXPECT_EQ(w->preferences().autosave_seconds, 7);
        EXPECT_TRUE(w->view_options().swap_modifiers);
        EXPECT_TRUE(w->view_options().visible_only);
        EXPECT_EQ(w->tree_panel().findChild<QComboBox*>("color_by")->currentIndex(), 1);
    }
    // The next window starts with them; the command line's --autosave wins for its session.
    editor::StartOptions start = test_start(dir);
    start.autosave_seconds = -1;
    editor::MainWindow next(start);
    EXPECT_EQ(next.preferences().autosave_seconds, 7);
    EXPECT_TRUE(next.view_options().swap_modifiers);
    EXPECT_TRUE(next.view_options().visible_only);
    start.autosave_seconds = 0;
    editor::MainWindow overridden(start);
    EXPECT_EQ(overridden.preferences().autosave_seconds, 0);
    // Back to the defaults, so the other tests of this binary start clean.
    overridden.apply_preferences(editor::Preferences{});
}

TEST(EditorSession, ALargeNodeIsBuiltInTheBackgroundAndAnEditMeanwhileDropsTheResult) {
    TempDir dir("editor-background-build");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    w->set_background_build_samples(0); // every node counts as large
    // What the same build gives at once, for comparison.
    SamplingTree expected = w->document().tree();
    ASSERT_TRUE(expected.build_subtree(w->document().current(), w->document().samples(),
                                       w->tree_panel().build_options()));
    ASSERT_TRUE(w->build_subtree());
    EXPECT_FALSE(w->build_subtree()) << "a second build started while one was running";
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->building() && w->undo_stack().count() == 1; }, 120000))
        << w->last_message().toStdString();
    SptDocument with_expected = w->document().document();
    with_expected.trees[size_t(w->document().tree_index())] = expected;
    EXPECT_EQ(encode_spt(w->document().document()), encode_spt(with_expected));
    // An edit while building: the result would overwrite it, so it is dropped.
    w->undo_stack().undo();
    ASSERT_TRUE(w->build_subtree());
    ASSERT_TRUE(w->add_tree("meanwhile"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->building(); }, 120000));
    QTest::qWait(50);
    EXPECT_EQ(w->undo_stack().count(), 1) << "the stale build was pushed";
    EXPECT_TRUE(w->last_message().contains("not applied")) << w->last_message().toStdString();
}

TEST(EditorSession, CancelBuildStopsCoresBuilderAndKeepsTheDocument) {
    // 80,000 samples in the root: a build far longer than the click that follows its start.
    TempDir dir("editor-cancel-build");
    const std::string mesh = dir.file("big.obj"), spt = dir.file("big.spt");
    meshgen::write_obj(meshgen::torus(1, 0.4, 400, 200), mesh);
    ConvertOptions o;
    o.auto_tolerance = false;
    SptDocument doc = make_document(import_mesh(mesh).mesh, o);
    doc.trees = {unsplit_tree("authored", doc.samples)};
    save_spt(doc, spt);
    std::string error;
    const auto w = open_editor(dir, QString::fromStdString(spt), &error);
    ASSERT_TRUE(w) << error;
    const std::vector<uint8_t> before = w->document().encode();
    ASSERT_TRUE(w->build_subtree());
    auto* cancel = w->findChild<QPushButton*>("cancel_build");
    ASSERT_NE(cancel, nullptr);
    ASSERT_TRUE(cancel->isVisible());
    // click(), not a QTest mouse click: that one repaints the four views first (over 100 ms
    // here), time in which the build could end, and then there would be nothing to stop.
    cancel->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->building(); }, 120000));
    // Core saw the flag and stopped; a build that ran to its end would say so.
    EXPECT_EQ(w->last_message(), "building the subtree cancelled");
    EXPECT_EQ(w->undo_stack().count(), 0);
    EXPECT_EQ(w->document().encode(), before);
    // Nothing is left behind: the next build runs and is applied.
    ASSERT_TRUE(w->build_subtree());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->building() && w->undo_stack().count() == 1; }, 120000))
        << w->last_message().toStdString();
    EXPECT_GT(w->document().tree().node_count(), 1u);
}

TEST(EditorSession, TheTreePanelShowsManyRowsBesideTheHistoryAndCostTabs) {
    // The cost tab's chart and table once set the lower dock group's least height, and the
    // node table above it showed three rows in an 860-pixel window.
    TempDir dir("editor-session-rows");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    ASSERT_GE(w->height(), 800); // the window opens at 1280x860
    QTreeWidget* nodes = w->tree_panel().nodes();
    const int row = nodes->fontMetrics().height();
    EXPECT_GE(nodes->viewport()->height(), 15 * row) << "the node table shows "
                                                      << nodes->viewport()->height() / row << " rows";
    // The cost tab is whole when scrolled: a scroll area holds it, not the dock's height.
    w->findChild<QDockWidget*>("cost_dock")->raise();
    QTest::qWait(50);
    auto* scroll = qobject_cast<QScrollArea*>(w->findChild<QDockWidget*>("cost_dock")->widget());
    ASSERT_TRUE(scroll);
    EXPECT_EQ(scroll->widget(), &w->cost_panel());
}

TEST(EditorSession, AStartWithNoFileSaysHowToOpenOneAndEveryViewIsNamed) {
    // A first start showed four empty views, an "Opened" history with nothing opened and a
    // sampling radius of 0.000001 that no node had.
    TempDir dir("editor-session-empty");
    editor::MainWindow w(test_start(dir));
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    const char* names[4] = {"Top", "Front", "Side", "Camera"};
    for (int i = 0; i < 4; ++i) {
        auto* title = w.grid().view(i)->findChild<QLabel*>("view_title");
        ASSERT_TRUE(title) << names[i];
        EXPECT_EQ(title->text().toStdString(), names[i]);
        EXPECT_TRUE(title->isVisible()) << names[i];
        EXPECT_TRUE(title->testAttribute(Qt::WA_TransparentForMouseEvents)) << "a drag starting on it must still select";
    }
    const QLabel& hint = w.grid().empty_hint();
    EXPECT_TRUE(hint.isVisible());
    EXPECT_TRUE(hint.text().contains("Open a mesh or a .spt file")) << hint.text().toStdString();
    auto* history = w.findChild<QUndoView*>();
    ASSERT_TRUE(history);
    EXPECT_EQ(history->emptyLabel().toStdString(), "No document");
    auto* build = w.tree_panel().findChild<QPushButton*>("build_subtree");
    auto* radius = w.tree_panel().findChild<QDoubleSpinBox*>("sampling_radius");
    ASSERT_TRUE(build && radius);
    EXPECT_FALSE(build->isEnabled());
    EXPECT_FALSE(radius->isEnabled());
    EXPECT_EQ(radius->text().toStdString(), "-");
    EXPECT_FALSE(w.split()) << "nothing to split";
    EXPECT_TRUE(w.last_message().contains("no document")) << w.last_message().toStdString();

    const EditorFiles files = write_editor_files(dir);
    w.open_file(files.spt);
    ASSERT_TRUE(wait_ready(w)) << w.last_error().toStdString();
    EXPECT_FALSE(hint.isVisible());
    EXPECT_EQ(history->emptyLabel().toStdString(), "Opened torus.spt");
    EXPECT_TRUE(build->isEnabled());
    EXPECT_TRUE(radius->isEnabled());
    EXPECT_EQ(radius->value(), double(w.document().tree().find(w.document().current())->ss_radius));
    EXPECT_NE(radius->text().toStdString(), "-");
}

TEST(EditorSession, TheRadiusBoxKeepsRadiiOfModelsAThousandthOfAUnitAcrossAndTakesScientificNotation) {
    // With six fixed decimals, a radius of 1.2e-7 showed, and was set, as 0.000001.
    editor::RadiusBox box;
    box.setValue(1.234567e-7);
    EXPECT_EQ(box.value(), 1.234567e-7);
    EXPECT_EQ(box.text().toStdString(), "1.23457e-07");
    box.setValue(350.0);
    EXPECT_EQ(box.text().toStdString(), "350");
    box.show();
    box.setFocus();
    box.selectAll();
    QTest::keyClicks(&box, "2.5e-8");
    QTest::keyClick(&box, Qt::Key_Return);
    EXPECT_EQ(box.value(), 2.5e-8);
    box.selectAll();
    QTest::keyClicks(&box, "abc"); // not a number: refused as typed, the value kept
    QTest::keyClick(&box, Qt::Key_Return);
    EXPECT_EQ(box.value(), 2.5e-8);
    box.stepUp(); // a tenth of the leading digit
    EXPECT_NEAR(box.value(), 2.6e-8, 1e-20);
}

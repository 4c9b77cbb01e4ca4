// Opening and saving: byte-identical saves, Ctrl+S to -o, converted meshes, bad files and
// mismatched meshes reported with the document kept, the modified mark.
#include "editor_support.hpp"
#include "meshgen.hpp"
#include "spt/recipe.hpp"
#include <QPushButton>
#include <QFile>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

using namespace spt;
using namespace spt::test;

namespace {

std::vector<uint8_t> bytes_of(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

bool wait_opened(editor::MainWindow& w) {
    return QTest::qWaitFor([&] { return !w.loading(); }, 120000);
}

} // namespace

TEST(EditorFiles, OpenAndSaveWithoutEditsIsByteIdentical) {
    TempDir dir("editor-save");
    const EditorFiles files = write_editor_files(dir);
    editor::StartOptions start = test_start(dir);
    start.file = files.spt;
    start.output = QString::fromStdString(dir.file("out.spt"));
    editor::MainWindow w(start);
    w.show();
    ASSERT_TRUE(wait_ready(w)) << w.last_error().toStdString();
    EXPECT_FALSE(w.modified());
    EXPECT_FALSE(w.isWindowModified());
    EXPECT_TRUE(w.windowTitle().startsWith("out.spt[*]")) << w.windowTitle().toStdString();
    // Ctrl+S writes to -o without a dialog.
    QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
    ASSERT_TRUE(std::filesystem::exists(dir.file("out.spt"))) << w.last_message().toStdString();
    EXPECT_EQ(bytes_of(dir.file("out.spt")), bytes_of(files.spt.toStdString()));
}

TEST(EditorFiles, AnEditSetsTheModifiedMarkAndASaveClearsIt) {
    TempDir dir("editor-modified");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    ASSERT_TRUE(w.add_tree("walking"));
    EXPECT_TRUE(w.isWindowModified());
    ASSERT_TRUE(w.save_to(QString::fromStdString(dir.file("edited.spt"))));
    EXPECT_FALSE(w.isWindowModified());
    EXPECT_NE(load_spt(dir.file("edited.spt")).tree("walking"), nullptr);
    w.undo_stack().undo();
    EXPECT_TRUE(w.isWindowModified());
    w.undo_stack().redo();
    EXPECT_FALSE(w.isWindowModified());
}

TEST(EditorFiles, AMeshIsConvertedToAnUnsplitTreeAndCountsAsUnsaved) {
    TempDir dir("editor-convert");
    const EditorFiles files = write_editor_files(dir);
    std::string error;
    const auto window = open_editor(dir, files.mesh, &error);
    ASSERT_TRUE(window) << error;
    const editor::EditorDocument& d = window->document();
    ASSERT_NE(d.mesh(), nullptr);
    EXPECT_EQ(d.document().trees.size(), 1u);
    EXPECT_EQ(d.tree().node_count(), 1u);
    EXPECT_EQ(d.tree().validate(uint32_t(d.samples().size())), "");
    // Default conversion options: the same samples `spt convert` makes.
    EXPECT_EQ(d.samples().size(), make_document(import_mesh(files.mesh.toStdString()).mesh).samples.size());
    EXPECT_TRUE(window->modified());
}

TEST(EditorFiles, ABadFileIsReportedByNameAndTheDocumentIsKept) {
    TempDir dir("editor-bad");
    const EditorFiles files = write_editor_files(dir);
    std::string error;
    const auto window = open_editor(dir, files.spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    // An edit, saved, so opening the next file does not stop to ask about unsaved changes.
    ASSERT_TRUE(w.add_tree("kept"));
    ASSERT_TRUE(w.save_to(QString::fromStdString(dir.file("kept.spt"))));
    const std::vector<uint8_t> before = w.document().encode();
    // A .spt file cut short, a file that is no mesh, and a missing file.
    std::vector<uint8_t> cut = bytes_of(files.spt.toStdString());
    cut.resize(cut.size() / 2);
    std::ofstream(dir.file("cut.spt"), std::ios::binary).write(reinterpret_cast<const char*>(cut.data()), std::streamsize(cut.size()));
    std::ofstream(dir.file("junk.obj")) << "this is not a mesh\n";
    for (const std::string name : {"cut.spt", "junk.obj", "missing.ply"}) {
        w.open_file(QString::fromStdString(dir.file(name)));
        ASSERT_TRUE(wait_opened(w));
        EXPECT_NE(w.last_error().indexOf(QString::fromStdString(dir.file(name))), -1) << w.last_error().toStdString();
        EXPECT_EQ(w.document().encode(), before) << name;
        EXPECT_EQ(w.undo_stack().count(), 1);
    }
    EXPECT_NE(w.last_error().indexOf("no such file"), -1) << w.last_error().toStdString();
}

TEST(EditorFiles, CancelStopsAConversionInsideCoreAndKeepsTheDocument) {
    TempDir dir("editor-cancel");
    const EditorFiles files = write_editor_files(dir);
    std::string error;
    const auto window = open_editor(dir, files.spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    const std::vector<uint8_t> before = w.document().encode();
    // About a second of conversion: the click lands while it runs (before it, at worst).
    const std::string big = dir.file("big.ply");
    meshgen::write_ply(meshgen::torus(1, 0.4, 400, 200), big);
    w.open_file(QString::fromStdString(big));
    auto* cancel = w.findChild<QPushButton*>("cancel_open");
    ASSERT_NE(cancel, nullptr);
    ASSERT_TRUE(cancel->isVisible());
    QTest::mouseClick(cancel, Qt::LeftButton);
    ASSERT_TRUE(wait_opened(w));
    // Stopped in core: while reading the mesh or while converting it, whichever the click met.
    EXPECT_TRUE(w.last_message().contains("opening cancelled, the import stopped") ||
                w.last_message().contains("opening cancelled, the conversion stopped"))
        << w.last_message().toStdString();
    EXPECT_EQ(w.document().encode(), before);
    EXPECT_FALSE(w.modified());
    // The stopped worker leaves nothing behind: the next opening works.
    w.open_file(files.mesh);
    ASSERT_TRUE(wait_opened(w));
    EXPECT_EQ(w.document().tree().node_count(), 1u);
}

TEST(EditorFiles, LoadDocumentReportsACancelledConversionByName) {
    TempDir dir("editor-cancel-load");
    const EditorFiles files = write_editor_files(dir);
    std::atomic<bool> cancel{true};
    const editor::LoadResult r = editor::load_document(files.mesh, {}, &cancel);
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.doc);
    EXPECT_NE(r.error.indexOf(files.mesh), -1) << r.error.toStdString();
}

TEST(EditorFiles, AMissingOrMismatchedMeshIsReportedNotUsed) {
    TempDir dir("editor-mesh");
    const EditorFiles files = write_editor_files(dir);
    std::filesystem::create_directories(dir.file("alone"));
    const std::string alone = dir.file("alone/torus.spt");
    std::filesystem::copy_file(files.spt.toStdString(), alone);
    editor::StartOptions start = test_start(dir);
    start.file = QString::fromStdString(alone);
    {
        editor::MainWindow w(start);
        ASSERT_TRUE(wait_opened(w));
        EXPECT_TRUE(w.document().has_tree());
        EXPECT_EQ(w.document().mesh(), nullptr);
        EXPECT_NE(w.last_error().indexOf("was not found"), -1) << w.last_error().toStdString();
    }
    start.mesh = QString::fromStdString(project_meshes() + "/box.ply");
    editor::MainWindow w(start);
    ASSERT_TRUE(wait_opened(w));
    EXPECT_TRUE(w.document().has_tree());
    EXPECT_EQ(w.document().mesh(), nullptr);
    EXPECT_NE(w.last_error().indexOf("is not the mesh"), -1) << w.last_error().toStdString();
}

TEST(EditorFiles, ASplitByMouseRecordsItsRecipeAndTheRecipeReplays) {
    TempDir dir("editor-recipe");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    editor::ViewWidget* side = w.grid().view(2);
    QTest::mousePress(side, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseRelease(side, Qt::LeftButton, Qt::NoModifier, QPoint(side->width() - 1, side->height() / 2));
    editor::ViewWidget* camera = w.grid().view(3);
    QTest::mousePress(camera, Qt::LeftButton, Qt::ControlModifier, QPoint(1, 1));
    QTest::mouseRelease(camera, Qt::LeftButton, Qt::ControlModifier, QPoint(camera->width() / 3, camera->height() - 1));
    ASSERT_TRUE(w.split()) << w.last_message().toStdString();
    ASSERT_TRUE(w.save_to(QString::fromStdString(dir.file("authored.spt"))));
    const SptDocument saved = load_spt(dir.file("authored.spt"));
    const SamplingTree& t = saved.trees.front();
    ASSERT_EQ(t.recipe().size(), 1u);
    EXPECT_EQ(t.recipe().front().node, NodeId(1));
    ASSERT_EQ(t.recipe().front().strokes.size(), 2u);
    EXPECT_EQ(t.recipe().front().strokes[1].mode, SelectionMode::Subtract);
    EXPECT_TRUE(t.recipe().front().strokes[1].view.perspective);
    // On the same mesh the replay gives the same split.
    ReplayReport report;
    const SamplingTree again = replay_recipe(t, saved.samples, *w.document().mesh(), &report);
    EXPECT_EQ(report.replayed, 1u);
    EXPECT_EQ(again.find(2)->samples, t.find(2)->samples);
    EXPECT_EQ(again.find(3)->samples, t.find(3)->samples);
}

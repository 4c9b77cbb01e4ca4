#pragma once
// Helpers for the editor's UI tests: a QApplication on xcb (made once per binary, before
// which the GL format is set), test documents written to a temporary folder, and waits.
#include "main_window.hpp"
#include "test_support.hpp"
#include <QString>
#include <memory>

namespace spt::test {

/// A torus mesh and its .spt (vertex samples only, so edits stay small) in `dir`.
struct EditorFiles {
    QString mesh; ///< torus.obj
    QString spt;  ///< torus.spt from torus.obj, vertex samples only: trees 'authored' (root only) and 'default'
};

/// Writes the test mesh and document into `dir`.
EditorFiles write_editor_files(const TempDir& dir);

/// Options that keep a test window away from the user's settings and recovery files.
editor::StartOptions test_start(const TempDir& dir);

/// Waits until the window has finished opening and every view has drawn; false on timeout.
bool wait_ready(editor::MainWindow& window);

/// Waits until every view has drawn (with its camera fitted, after frame_all); false on timeout.
bool wait_drawn(editor::MainWindow& window);

/// A shown window (test_start options) that has opened `file` and drawn every view; null
/// (with the reason in `error`) if it did not get there.
std::unique_ptr<editor::MainWindow> open_editor(const TempDir& dir, const QString& file, std::string* error);

/// Expects view `view`'s framebuffer to equal `spt render INPUT_ARGS --view V --size WxH -o PNG`
/// of the same view and size (the golden rules), the PNG written into `dir`; a difference is
/// written to editor_output_dir()/NAME_V.diff.png.
void expect_view_matches_spt_render(editor::ViewWidget& view, const QStringList& input_args, const TempDir& dir,
                                    const std::string& name);

/// A view's projection as a test derives it from the camera and the widget's size (not from the
/// view's own view_projection(), which is what is being tested).
ViewProjection reference_projection(const editor::ViewWidget& v);

/// Where the tests write pictures (docs/editor.md uses them): BUILD/test-output/editor.
std::string editor_output_dir();

} // namespace spt::test

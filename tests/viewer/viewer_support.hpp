#pragma once
// Helpers for the viewer's UI tests: the binary's one QApplication (xcb, GL format set
// first), test scenes written to a temporary folder, waits, and grabs as render::Image.
#include "qt_image.hpp"
#include "render/golden.hpp"
#include "spt/render/image.hpp"
#include "test_support.hpp"
#include "viewer_window.hpp"
#include <QImage>
#include <QString>
#include <memory>

namespace spt::test {

/// A scene of the bundled crate dropped on the bundled slab (models by absolute path), with
/// `steps` steps and the given effects (JSON array text), written to dir/drop.json.
QString write_drop_scene(const TempDir& dir, int steps, const char* effects_json);

/// A shown viewer window opening `scene` at `step` in `view` with `overlays`, its view fixed at
/// 320 x 240 logical pixels (the size the frame comparisons render with `spt render`).
std::unique_ptr<editor::ViewerWindow> show_viewer(const QString& scene, const editor::ViewerOverlays& overlays,
                                                  render::View view, int step);

/// Waits until `w` shows a loaded scene recorded up to step `k` (or finished); false on timeout.
bool wait_recorded(editor::ViewerWindow& w, int k, int timeout_ms = 120000);

/// Waits until the window is active, no scene is loading or being recorded again and the view
/// has drawn; false on timeout.
bool wait_idle(editor::ViewerWindow& w, int timeout_ms = 120000);

/// `spt render` of a scene frame, as the viewer's test compares it: alpha made opaque (a window
/// shows colour only). Empty image with the reason in `error` if the command failed.
render::Image spt_render_frame(const TempDir& dir, const QString& scene, int frame, const char* view, QSize size,
                               const QString& overlays, std::string* error);

/// Shows `step` in `view` and compares the grabbed frame with `spt render` of the same scene, step,
/// view, size and overlays (the goldens' rule). `shown` receives the grab, `error` why `spt render`
/// failed (the result then does not pass).
render::CompareResult compare_with_spt_render(editor::ViewerWindow& w, const TempDir& dir, const QString& scene, int step,
                                              render::View view, const QString& overlays, render::Image& shown,
                                              std::string& error);

/// Where the tests write pictures: BUILD/test-output/viewer.
std::string viewer_output_dir();

} // namespace spt::test

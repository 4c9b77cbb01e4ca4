#pragma once
// spt-viewer's command line: parsed into a ViewerStart, with a message naming the bad option.
#include "viewer_window.hpp"
#include <QSize>
#include <QStringList>

namespace spt::editor {

/// A parsed command line.
struct ViewerCommandLine {
    ViewerStart start; ///< what the window opens and shows
    QSize view_size;   ///< fixed view size in logical pixels (--size); invalid: the window decides
    QString error;     ///< non-empty: the usage error (exit 2)
};

/// Parses `spt-viewer [SCENE.json] [--step N] [--view V] [--overlay LIST] [--speed X] [--play]
/// [--size WxH]` (arguments after the program name, QApplication's own already removed).
ViewerCommandLine parse_viewer_arguments(const QStringList& arguments);

/// The --help text.
QString viewer_usage();

} // namespace spt::editor

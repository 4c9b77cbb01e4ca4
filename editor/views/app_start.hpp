#pragma once
// What spt-editor and spt-viewer do before their QApplication exists: answer --help without a
// display, and turn Qt's abort when no window system can be reached into a message and an exit code.
#include <QStringList>

namespace spt::editor {

/// Exit code of spt-editor and spt-viewer when no window system can be opened (no display).
constexpr int kExitNoWindowSystem = 3;

/// The command line as QCoreApplication::arguments() gives it, read from argv before any
/// application object exists (Qt's own options, such as -platform, are still in it).
QStringList arguments_before_app(int argc, char** argv);

/// Whether the command line asks for help (-h, --help, --help-all, -?), which needs no display.
bool asks_for_help(const QStringList& arguments);

/// From now until window_system_started(): if Qt cannot start its platform plugin (no
/// DISPLAY, an X server that refuses, an unknown QT_QPA_PLATFORM), prints why on stderr
/// naming `program` and ends the process with kExitNoWindowSystem, where Qt would abort
/// with a core dump. Other messages go to the handler that was installed before.
void exit_cleanly_without_window_system(const char* program);

/// Ends exit_cleanly_without_window_system: Qt's own handling of fatal messages is back.
void window_system_started();

} // namespace spt::editor

// Starts a QGuiApplication on the offscreen platform for programs that have none.
#include "spt/plot/headless_gui.hpp"
#include <QGuiApplication>
#include <stdexcept>

namespace spt::plot {
namespace {

// QGuiApplication keeps references to argc and argv for its whole life, and may reorder argv.
int g_argc = 0;
char g_name[] = "spt-plot", g_option[] = "-platform", g_platform[] = "offscreen";
char* g_argv[4] = {};
QtMessageHandler g_previous = nullptr;

// Drops the one startup warning a headless program cannot act on (no XDG_RUNTIME_DIR under cron, CI or ssh; Qt
// falls back to /tmp/runtime-<user> by itself) and passes every other message on.
void without_runtime_dir_warning(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (type == QtWarningMsg && message.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR not set"))) return;
    g_previous(type, context, message);
}

} // namespace

HeadlessGui::HeadlessGui() {
    QCoreApplication* existing = QCoreApplication::instance();
    if (qobject_cast<QGuiApplication*>(existing)) return; // an app (the editor, a UI test) already has fonts
    if (existing)
        throw std::runtime_error("spt::plot needs a QGuiApplication to draw text, but this program made a QCoreApplication");
    // Text needs Qt's font database, which only a platform plugin provides, and only a QGuiApplication loads one
    // (a QFont made before it aborts the program). The default plugin, xcb, aborts when there is no X server (CI,
    // ssh, cron), and QT_QPA_PLATFORM may name any plugin. `-platform offscreen` in the arguments we hand Qt
    // overrides both, without changing the environment that child processes inherit. The offscreen plugin ships
    // in libqt6gui6, needs no display, and takes its fonts from fontconfig like the desktop plugins, so a chart
    // drawn here has the same type as one drawn in the editor.
    g_argv[0] = g_name, g_argv[1] = g_option, g_argv[2] = g_platform, g_argv[3] = nullptr;
    g_argc = 3;
    g_previous = qInstallMessageHandler(without_runtime_dir_warning);
    app_ = std::make_unique<QGuiApplication>(g_argc, g_argv);
    qInstallMessageHandler(g_previous);
}

HeadlessGui::~HeadlessGui() = default;

} // namespace spt::plot

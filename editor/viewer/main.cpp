// spt-viewer [SCENE.json] [options]: plays a scene's simulation (docs/viewer.md).
#include "app_start.hpp"
#include "viewer_options.hpp"
#include "viewer_window.hpp"
#include <QApplication>
#include <cstdio>

int main(int argc, char** argv) {
    if (spt::editor::asks_for_help(spt::editor::arguments_before_app(argc, argv))) { // no display needed
        std::fputs(qPrintable(spt::editor::viewer_usage()), stdout);
        return 0;
    }
    // Before QApplication: the view's context is 3.3 core (render/ needs it).
    spt::editor::use_render_gl_format();
    spt::editor::exit_cleanly_without_window_system("spt-viewer");
    QApplication app(argc, argv);
    spt::editor::window_system_started();
    QApplication::setApplicationName("spt-viewer");
    QApplication::setOrganizationName("spt");
    QStringList args = QApplication::arguments(); // Qt's own options (-platform, -display) taken out
    args.removeFirst();
    const spt::editor::ViewerCommandLine c = spt::editor::parse_viewer_arguments(args);
    if (!c.error.isEmpty()) {
        std::fprintf(stderr, "spt-viewer: %s\n%s", qPrintable(c.error), qPrintable(spt::editor::viewer_usage()));
        return 2;
    }
    spt::editor::ViewerWindow window(c.start);
    if (c.view_size.isValid()) window.view()->setFixedSize(c.view_size);
    window.show();
    return app.exec();
}

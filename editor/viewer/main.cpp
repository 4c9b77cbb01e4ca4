// spt-viewer [SCENE.json] [options]: plays a scene's simulation (docs/viewer.md).
#include "viewer_options.hpp"
#include "viewer_window.hpp"
#include <QApplication>
#include <cstdio>

int main(int argc, char** argv) {
    // Before QApplication: the view's context is 3.3 core (render/ needs it).
    spt::editor::use_render_gl_format();
    QApplication app(argc, argv);
    QApplication::setApplicationName("spt-viewer");
    QApplication::setOrganizationName("spt");
    QStringList args = QApplication::arguments();
    args.removeFirst();
    if (args.contains("--help") || args.contains("-h")) {
        std::fputs(qPrintable(spt::editor::viewer_usage()), stdout);
        return 0;
    }
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

// spt-editor [FILE] [-o OUT.spt] [--mesh MESH] [--autosave SECONDS] [--scene SCENE.json [--object NAME]
// [--motion-steps N]]: the four-view sampling editor.
#include "app_start.hpp"
#include "main_window.hpp"
#include "motion_session.hpp"
#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>
#include <cstdio>

namespace {

void describe(QCommandLineParser& parser) {
    parser.setApplicationDescription("The four-view sampling editor (docs/editor.md). Exit codes: 0 ok, 2 bad command "
                                     "line, 3 no window system (no display).");
    parser.addHelpOption();
    parser.addPositionalArgument("FILE", "A mesh (converted with default options) or a .spt file");
    parser.addOption({{"o", "output"}, "Where Save (Ctrl+S) writes, without a dialog", "OUT.spt"});
    parser.addOption({"mesh", "The .spt file's mesh, if it is not beside it", "MESH"});
    parser.addOption({"autosave", "Seconds between recovery files for this session (default: the preference, 30; 0: off)", "SECONDS"});
    parser.addOption({"scene", "Load the motion of an object of this scene once FILE is open (File > Load motion)", "SCENE.json"});
    parser.addOption({"object", "The scene's object whose model FILE is (default: the one whose model or mesh is FILE's)", "NAME"});
    parser.addOption({"motion-steps", "Steps of the scene to record (default: the scene's own)", "N"});
}

} // namespace

int main(int argc, char** argv) {
    QCommandLineParser parser;
    describe(parser);
    if (spt::editor::asks_for_help(spt::editor::arguments_before_app(argc, argv))) { // no display needed
        std::fputs(qPrintable(parser.helpText().replace("<executable_name>", "spt-editor")), stdout);
        return 0;
    }
    // Before QApplication: every view's context is 3.3 core (render/ needs it).
    spt::editor::use_render_gl_format();
    spt::editor::exit_cleanly_without_window_system("spt-editor");
    QApplication app(argc, argv);
    spt::editor::window_system_started();
    QApplication::setApplicationName("spt-editor");
    QApplication::setOrganizationName("spt");

    // Parsed after QApplication, which takes Qt's own options (-platform, -display) out.
    if (!parser.parse(QApplication::arguments())) {
        std::fprintf(stderr, "spt-editor: %s\n", qPrintable(parser.errorText()));
        return 2;
    }

    spt::editor::StartOptions options;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        std::fprintf(stderr, "spt-editor: one FILE at most (got %d)\n", int(files.size()));
        return 2;
    }
    bool ok = true;
    if (parser.isSet("autosave")) options.autosave_seconds = parser.value("autosave").toInt(&ok);
    // At most a day, as the preferences allow: the timer counts milliseconds in an int.
    if (!ok || (parser.isSet("autosave") && (options.autosave_seconds < 0 || options.autosave_seconds > 86400))) {
        std::fprintf(stderr, "spt-editor: --autosave %s: expected a whole number of seconds from 0 to 86400\n",
                     qPrintable(parser.value("autosave")));
        return 2;
    }
    if (!files.isEmpty()) options.file = files.front();
    // A motion: the scene must be readable and hold the object, before any window.
    if ((parser.isSet("object") || parser.isSet("motion-steps")) && !parser.isSet("scene")) {
        std::fprintf(stderr, "spt-editor: --object and --motion-steps need --scene SCENE.json\n");
        return 2;
    }
    if (parser.isSet("scene")) {
        if (files.isEmpty()) {
            std::fprintf(stderr, "spt-editor: --scene needs FILE: the model whose tree runs in the scene\n");
            return 2;
        }
        options.scene = parser.value("scene");
        options.object = parser.value("object");
        const spt::editor::SceneObjects objects = spt::editor::read_scene_objects(options.scene);
        if (!objects.error.isEmpty()) {
            std::fprintf(stderr, "spt-editor: --scene %s\n", qPrintable(objects.error));
            return 2;
        }
        if (!options.object.isEmpty() && !objects.names.contains(options.object)) {
            std::fprintf(stderr, "spt-editor: --object %s: %s has no object of that name; it has '%s'\n",
                         qPrintable(options.object), qPrintable(options.scene), qPrintable(objects.names.join("', '")));
            return 2;
        }
        if (parser.isSet("motion-steps")) options.motion_steps = parser.value("motion-steps").toInt(&ok);
        if (!ok || options.motion_steps < 0 || options.motion_steps > (1 << 24)) {
            std::fprintf(stderr, "spt-editor: --motion-steps %s: expected a whole number of steps from 0 to 16777216\n",
                         qPrintable(parser.value("motion-steps")));
            return 2;
        }
    }
    options.output = parser.value("output");
    options.mesh = parser.value("mesh");

    spt::editor::MainWindow window(options);
    window.show();
    // After the window is up, so the question has a parent to sit on.
    QTimer::singleShot(0, &window, [&window] { window.offer_recovery(); });
    return app.exec();
}

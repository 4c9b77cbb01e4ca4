// Start-up of the Qt apps: help and a missing display handled before Qt would abort.
#include "app_start.hpp"
#include <QByteArray>
#include <QString>
#include <QtGlobal>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace spt::editor {
namespace {

QtMessageHandler previous_handler = nullptr;
std::string program_name;

void refuse_without_window_system(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (type != QtFatalMsg) {
        if (previous_handler) previous_handler(type, context, message);
        else std::fprintf(stderr, "%s\n", qPrintable(message));
        return;
    }
    // The only fatal message a QApplication's constructor gives is that no platform plugin
    // could be initialised; Qt would abort (a core dump) right after this returns.
    const QString platform = QString::fromLocal8Bit(qgetenv("QT_QPA_PLATFORM"));
    const QString display = QString::fromLocal8Bit(qgetenv("DISPLAY"));
    const QString why = QString("%1 could not start; %2")
                            .arg(platform.isEmpty() ? QString("Qt's default platform plugin")
                                                    : QString("Qt's platform plugin '%1'").arg(platform),
                                 display.isEmpty() ? QString("DISPLAY is not set") : QString("DISPLAY is %1").arg(display));
    std::fprintf(stderr,
                 "%s: cannot open a window: %s. Run it on a desktop, or under a virtual display: xvfb-run -a %s ...\n",
                 program_name.c_str(), qPrintable(why), program_name.c_str());
    std::fflush(stderr);
    std::_Exit(kExitNoWindowSystem); // not exit(): the half-built QApplication must not be destroyed
}

} // namespace

QStringList arguments_before_app(int argc, char** argv) {
    QStringList out;
    for (int i = 0; i < argc; ++i) out << QString::fromLocal8Bit(argv[i]);
    return out;
}

bool asks_for_help(const QStringList& arguments) {
    for (int i = 1; i < arguments.size(); ++i) {
        const QString& a = arguments[i];
        if (a == "--") break; // what follows is a file name
        if (a == "-h" || a == "--help" || a == "--help-all" || a == "-?") return true;
    }
    return false;
}

void exit_cleanly_without_window_system(const char* program) {
    program_name = program;
    previous_handler = qInstallMessageHandler(refuse_without_window_system);
}

void window_system_started() {
    qInstallMessageHandler(previous_handler);
    previous_handler = nullptr;
}

} // namespace spt::editor

// Parsing spt-viewer's command line.
#include "viewer_options.hpp"

namespace spt::editor {

QString viewer_usage() {
    return "usage: spt-viewer [SCENE.json] [--step N] [--view top|front|side|camera] [--overlay LIST]\n"
           "                  [--speed X] [--play] [--size WxH]\n"
           "Plays a scene's simulation (docs/viewer.md). Overlays (comma-separated, as `spt render`):\n"
           "contacts, normals, manifold, pairs, ghost, trails, spheres, bounds, broad, grid, axes, none\n"
           "(default grid,axes). Keys: Space play/pause, Right/Left step, Home/End first/last step,\n"
           "F frame all, F5 reload. Exit codes: 0 ok, 2 bad arguments, 3 no window system (no display).\n";
}

ViewerCommandLine parse_viewer_arguments(const QStringList& args) {
    ViewerCommandLine c;
    auto fail = [&c](const QString& message) {
        c.error = message;
        return c;
    };
    auto value = [&args](int& i) -> QString { return i + 1 < args.size() ? args[++i] : QString(); };
    QStringList files;
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == "--step") {
            bool ok = false;
            const QString v = value(i);
            c.start.step = v.toInt(&ok);
            if (!ok || c.start.step < 0) return fail(QString("--step %1: expected a whole number >= 0").arg(v));
        } else if (a == "--view") {
            const QString v = value(i);
            if (v == "top") c.start.view = render::View::Top;
            else if (v == "front") c.start.view = render::View::Front;
            else if (v == "side") c.start.view = render::View::Side;
            else if (v == "camera") c.start.view = render::View::Camera;
            else return fail(QString("--view %1: expected top, front, side or camera").arg(v));
        } else if (a == "--overlay") {
            const QString v = value(i);
            ViewerOverlays o;
            o.grid = o.axes = false;
            for (const QString& n : v.split(',', Qt::SkipEmptyParts)) {
                if (bool* flag = o.flag(n.toStdString())) *flag = true;
                else if (n != "none") return fail(QString("--overlay %1: unknown overlay '%2'").arg(v, n));
            }
            if (v.isEmpty()) return fail("--overlay: expected a comma-separated list");
            c.start.overlays = o;
        } else if (a == "--speed") {
            bool ok = false;
            const QString v = value(i);
            c.start.speed = v.toDouble(&ok);
            if (!ok || !(c.start.speed >= 0.01 && c.start.speed <= 100))
                return fail(QString("--speed %1: expected a number from 0.01 to 100").arg(v));
        } else if (a == "--play") {
            c.start.play = true;
        } else if (a == "--size") {
            const QString v = value(i);
            const QStringList wh = v.split('x');
            bool ok_w = false, ok_h = false;
            const int w = wh.size() == 2 ? wh[0].toInt(&ok_w) : 0, h = wh.size() == 2 ? wh[1].toInt(&ok_h) : 0;
            if (!ok_w || !ok_h || w < 80 || h < 60 || w > 8192 || h > 8192)
                return fail(QString("--size %1: expected WxH, 80x60 to 8192x8192 logical pixels").arg(v));
            c.view_size = QSize(w, h);
        } else if (a.startsWith("-")) {
            return fail(QString("%1: unknown option").arg(a));
        } else {
            files << a;
        }
    }
    if (files.size() > 1) return fail(QString("one SCENE.json at most (got %1)").arg(files.size()));
    if (!files.isEmpty()) c.start.file = files.front();
    return c;
}

} // namespace spt::editor

#pragma once
// A QGuiApplication on the `offscreen` platform for programs that draw charts without a window.
#include <memory>

class QGuiApplication;

namespace spt::plot {

/// Keeps a QGuiApplication on the `offscreen` platform alive for its lifetime, so that a command-line program or a
/// test can draw text with real fonts and no display. Does nothing if the program already has a QGuiApplication;
/// throws std::runtime_error if it has a QCoreApplication (which cannot draw text). Main thread only.
class HeadlessGui {
public:
    /// Creates the application unless one exists.
    HeadlessGui();
    /// Destroys the application it created, if any.
    ~HeadlessGui();
    HeadlessGui(const HeadlessGui&) = delete;
    HeadlessGui& operator=(const HeadlessGui&) = delete;

private:
    std::unique_ptr<QGuiApplication> app_;
};

} // namespace spt::plot

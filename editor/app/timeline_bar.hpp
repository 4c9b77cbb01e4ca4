#pragma once
// The timeline under the views, shown while the document's mesh has animation clips: a clip box
// ("bind pose" first), a time slider and a spin box in seconds over the clip's duration,
// play/pause (real time, looping) and the time shown. Choosing a clip or a time is a view state
// (EditorDocument::set_pose), never an edit on the undo stack.
#include "editor_document.hpp"
#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace spt::editor {

/// Clip, time and play controls of an EditorDocument's pose.
class TimelineBar : public QWidget {
    Q_OBJECT
public:
    /// Slider steps a second: the slider moves in milliseconds.
    static constexpr int kStepsPerSecond = 1000;

    /// A bar over `doc`, which must outlive it; hidden until a document with clips is open.
    explicit TimelineBar(EditorDocument& doc, QWidget* parent = nullptr);

    /// The clip box: "bind pose", then the clips in file order.
    QComboBox* clips() const { return clips_; }
    /// The time slider (kStepsPerSecond steps a second).
    QSlider* slider() const { return slider_; }
    /// The time in seconds.
    QDoubleSpinBox* seconds() const { return seconds_; }
    /// Play / Pause.
    QPushButton* play_button() const { return play_; }
    /// The time shown and the clip's duration.
    QLabel* time_label() const { return label_; }
    /// True while the clip plays.
    bool playing() const { return timer_.isActive(); }
    /// Plays the chosen clip from the time shown, in real time, looping (nothing at the bind pose).
    void play();
    /// Stops playing; the pose stays.
    void pause();

signals:
    /// Playing started or stopped.
    void playingChanged(bool playing);

private:
    void document_reset();
    void show_pose();
    void tick();
    void choose(int clip, double time);
    EditorDocument& doc_;
    QComboBox* clips_ = nullptr;
    QSlider* slider_ = nullptr;
    QDoubleSpinBox* seconds_ = nullptr;
    QPushButton* play_ = nullptr;
    QLabel* label_ = nullptr;
    QTimer timer_;
    QElapsedTimer clock_; // since playing started or the time was moved meanwhile
    double play_from_ = 0; // the clip time when the clock started, seconds
    bool updating_ = false; // the controls are being set from the document
};

} // namespace spt::editor

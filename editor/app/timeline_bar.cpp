// TimelineBar: clip box, time slider and spin box, play/pause, all setting the document's pose.
#include "timeline_bar.hpp"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <cmath>

namespace spt::editor {
namespace {

// About 30 poses a second while playing; each pose's time comes from the clock, not from the
// ticks, so a slow frame delays the picture, not the clip.
constexpr int kTickMs = 33;

} // namespace

TimelineBar::TimelineBar(EditorDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    setObjectName("timeline");
    clips_ = new QComboBox;
    clips_->setObjectName("timeline_clip");
    clips_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    slider_ = new QSlider(Qt::Horizontal);
    slider_->setObjectName("timeline_slider");
    seconds_ = new QDoubleSpinBox;
    seconds_->setObjectName("timeline_seconds");
    seconds_->setDecimals(3);
    seconds_->setSingleStep(0.05);
    seconds_->setSuffix(" s");
    play_ = new QPushButton("Play");
    play_->setObjectName("timeline_play");
    label_ = new QLabel;
    label_->setObjectName("timeline_time");
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(6, 2, 6, 2);
    row->addWidget(new QLabel("Clip"));
    row->addWidget(clips_);
    row->addWidget(play_);
    row->addWidget(slider_, 1);
    row->addWidget(seconds_);
    row->addWidget(label_);

    connect(clips_, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!updating_) choose(index - 1, doc_.pose().time()); // the same time in another clip, held within it
    });
    connect(slider_, &QSlider::valueChanged, this, [this](int value) {
        if (!updating_) choose(doc_.pose().clip(), double(value) / kStepsPerSecond);
    });
    connect(seconds_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (!updating_) choose(doc_.pose().clip(), value);
    });
    connect(play_, &QPushButton::clicked, this, [this] { playing() ? pause() : play(); });
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &TimelineBar::tick);
    connect(&doc_, &EditorDocument::documentReset, this, &TimelineBar::document_reset);
    connect(&doc_, &EditorDocument::poseChanged, this, &TimelineBar::show_pose);
    connect(&doc_, &EditorDocument::poseRefused, this, &TimelineBar::show_pose); // back at the bind pose
    document_reset();
}

void TimelineBar::document_reset() {
    pause(); // the clip that played belongs to the document that closed
    updating_ = true;
    clips_->clear();
    clips_->addItem("bind pose");
    if (const AnimatedMesh* a = doc_.animation())
        for (const Clip& c : a->clips) clips_->addItem(QString::fromStdString(c.name));
    updating_ = false;
    // A mesh without clips shows no timeline: the editor as it was.
    setVisible(doc_.animation() != nullptr);
    show_pose();
}

void TimelineBar::show_pose() {
    const AnimatedMesh* a = doc_.animation();
    const int clip = doc_.pose().clip();
    const double t = doc_.pose().time();
    const double duration = a && clip >= 0 ? a->clips[size_t(clip)].duration : 0.0;
    updating_ = true;
    clips_->setCurrentIndex(clip + 1);
    slider_->setRange(0, int(std::lround(duration * kStepsPerSecond)));
    slider_->setPageStep(kStepsPerSecond / 10);
    slider_->setValue(int(std::lround(t * kStepsPerSecond)));
    seconds_->setRange(0, duration);
    seconds_->setValue(t);
    updating_ = false;
    const bool timed = duration > 0;
    slider_->setEnabled(timed);
    seconds_->setEnabled(timed);
    play_->setEnabled(timed);
    if (!timed) pause();
    label_->setText(clip < 0 ? QString("bind pose") : QString("%1 / %2 s").arg(t, 0, 'f', 3).arg(duration, 0, 'f', 3));
}

void TimelineBar::choose(int clip, double time) {
    doc_.set_pose(clip, time);
    // Playing goes on from the time chosen.
    play_from_ = doc_.pose().time();
    clock_.restart();
}

void TimelineBar::play() {
    const AnimatedMesh* a = doc_.animation();
    const int clip = doc_.pose().clip();
    if (playing() || !a || clip < 0 || !(a->clips[size_t(clip)].duration > 0)) return;
    play_from_ = doc_.pose().time();
    clock_.start();
    timer_.start();
    play_->setText("Pause");
    emit playingChanged(true);
}

void TimelineBar::pause() {
    if (!playing()) return;
    timer_.stop();
    play_->setText("Play");
    emit playingChanged(false);
}

void TimelineBar::tick() {
    const AnimatedMesh* a = doc_.animation();
    const int clip = doc_.pose().clip();
    if (!a || clip < 0) return pause();
    // Real time since play, from where it started, wrapped into the clip (core's clip_time).
    const double t = clip_time(a->clips[size_t(clip)], 1e-3 * double(clock_.elapsed()), 1, play_from_, true);
    doc_.set_pose(clip, t);
}

} // namespace spt::editor

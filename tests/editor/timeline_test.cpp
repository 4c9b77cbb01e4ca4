// The timeline of a mesh with animation clips, driven with real mouse and key events: it shows
// only for such a mesh, its slider changes what the views draw (the same time, the same
// picture), a rectangle at a posed time selects the samples where they are drawn then, a split
// made while posed records its pose and undoes and redoes, and Play runs until paused or until
// the document closes. The pose is a view state: nothing goes on the undo stack.
#include "editor_support.hpp"
#include "spt/selection.hpp"
#include "timeline_bar.hpp"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <gtest/gtest.h>
#include <filesystem>

using namespace spt;
using namespace spt::test;

namespace {

const QString kBar = QString(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf";

// Chooses clip `name` in the clip box from the keyboard (arrows: Home is the window's Frame all).
void choose_clip(editor::MainWindow& w, const QString& name) {
    QComboBox* box = w.timeline().clips();
    box->setFocus();
    for (int k = 0; k < box->count(); ++k) QTest::keyClick(box, Qt::Key_Up);
    for (int k = 0; k < box->count() && box->currentText() != name; ++k) QTest::keyClick(box, Qt::Key_Down);
    ASSERT_EQ(box->currentText(), name);
}

// Moves the slider to `tenths` tenths of a second from the keyboard: Page Down to the start,
// then Page Up, 0.1 s a press.
void slide_to(editor::MainWindow& w, int tenths) {
    QSlider* slider = w.timeline().slider();
    slider->setFocus();
    for (int k = 0; k <= slider->maximum() / slider->pageStep(); ++k) QTest::keyClick(slider, Qt::Key_PageDown);
    ASSERT_EQ(slider->value(), 0);
    for (int k = 0; k < tenths; ++k) QTest::keyClick(slider, Qt::Key_PageUp);
}

// What the four views draw now.
std::vector<QImage> pictures(editor::MainWindow& w) {
    std::vector<QImage> out;
    for (int i = 0; i < 4; ++i) out.push_back(w.grid().view(i)->grabFramebuffer());
    return out;
}

// Home (frame everything at the pose shown), then every view drawn through its new camera.
bool frame_all(editor::MainWindow& w) {
    QTest::keyClick(w.grid().view(0), Qt::Key_Home);
    return wait_drawn(w);
}

// Where the pose shown puts sample i's surface point, object frame.
Eigen::Vector3d posed_position(const editor::EditorDocument& d, uint32_t i) {
    return d.samples().origin + d.posed()->sample_points()[i].cast<double>();
}

// A drag in `v` from `from` to `to` (logical pixels) with the left button.
void drag(editor::ViewWidget* v, QPoint from, QPoint to, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    QTest::mousePress(v, Qt::LeftButton, mods, from);
    QTest::mouseMove(v, (from + to) / 2);
    QTest::mouseMove(v, to);
    QTest::mouseRelease(v, Qt::LeftButton, mods, to);
}

// Each test starts with bending_bar.gltf open (converted, at the bind pose) in a shown window.
class Timeline : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        window_ = open_editor(dir_, kBar, &error);
        ASSERT_TRUE(window_) << error;
    }
    editor::MainWindow& w() { return *window_; }
    // Saves the converted bar, so that closing it or opening another file asks nothing.
    void save() { ASSERT_TRUE(w().save_to(QString::fromStdString(dir_.file("bar.spt")))); }

    TempDir dir_{"editor-timeline"};
    std::unique_ptr<editor::MainWindow> window_;
};


TEST_F(Timeline, ShowsForAMeshWithClipsAndNotForOneWithout) {
    editor::MainWindow& w = this->w();
    ASSERT_NE(w.document().animation(), nullptr);
    EXPECT_TRUE(w.timeline().isVisible());
    QStringList names;
    for (int k = 0; k < w.timeline().clips()->count(); ++k) names << w.timeline().clips()->itemText(k);
    EXPECT_EQ(names, (QStringList{"bind pose", "linear", "step", "cubic"}));
    EXPECT_EQ(w.timeline().clips()->currentIndex(), 0);
    EXPECT_FALSE(w.timeline().play_button()->isEnabled()) << "the bind pose has no time to play";
    choose_clip(w, "step");
    EXPECT_EQ(w.timeline().slider()->maximum(), 2 * editor::TimelineBar::kStepsPerSecond) << "the clip's 2 s";
    EXPECT_DOUBLE_EQ(w.timeline().seconds()->maximum(), 2.0);
    EXPECT_TRUE(w.timeline().play_button()->isEnabled());

    // A mesh without clips: no timeline, the views as before it.
    window_.reset();
    std::string error;
    auto plain = open_editor(dir_, write_editor_files(dir_).spt, &error);
    ASSERT_TRUE(plain) << error;
    EXPECT_EQ(plain->document().animation(), nullptr);
    EXPECT_FALSE(plain->timeline().isVisible());
    EXPECT_EQ(plain->grid().height(), plain->centralWidget()->height());
}

TEST_F(Timeline, TheSliderPosesWhatTheViewsDrawAndTheSameTimeDrawsTheSamePicture) {
    editor::MainWindow& w = this->w();
    const std::vector<QImage> bind = pictures(w);
    choose_clip(w, "step");
    slide_to(w, 10);
    EXPECT_EQ(w.document().pose().clip(), 1); // "step", the second clip
    EXPECT_DOUBLE_EQ(w.document().pose().time(), 1.0);
    EXPECT_EQ(w.timeline().time_label()->text(), "1.000 / 2.000 s");
    ASSERT_NE(w.document().posed(), nullptr);
    const std::vector<QImage> at_one = pictures(w);
    for (int i = 0; i < 4; ++i) EXPECT_FALSE(at_one[size_t(i)] == bind[size_t(i)]) << "view " << i << " did not move";
    // Elsewhere, then the same time again: the same picture.
    slide_to(w, 5); // STEP holds the first key until 1 s: the bind pose's shape
    const std::vector<QImage> at_half = pictures(w);
    slide_to(w, 10);
    const std::vector<QImage> again = pictures(w);
    for (int i = 0; i < 4; ++i) {
        EXPECT_TRUE(again[size_t(i)] == at_one[size_t(i)]) << "view " << i;
        EXPECT_FALSE(at_half[size_t(i)] == at_one[size_t(i)]) << "view " << i;
    }
    // Back to the bind pose from the clip box: the picture it opened with.
    choose_clip(w, "bind pose");
    EXPECT_EQ(w.document().posed(), nullptr);
    const std::vector<QImage> back = pictures(w);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(back[size_t(i)] == bind[size_t(i)]) << "view " << i;
    // None of it was an edit.
    EXPECT_EQ(w.undo_stack().count(), 0);
    EXPECT_TRUE(w.undo_stack().isClean());
}

TEST_F(Timeline, ARectangleAtAPosedTimeSelectsTheSamplesWhereTheyAreDrawnThen) {
    editor::MainWindow& w = this->w();
    choose_clip(w, "step");
    slide_to(w, 10); // the tip half stands up along +y
    ASSERT_TRUE(frame_all(w));
    const editor::EditorDocument& d = w.document();
    editor::ViewWidget* front = w.grid().view(1);
    const ViewProjection view = front->view_projection();
    // A rectangle around where the standing tip (above y = 0.45) is drawn, from core's projection.
    float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    size_t tip = 0;
    for (uint32_t i = 0; i < d.samples().size(); ++i) {
        if (posed_position(d, i).y() < 0.45) continue;
        const Eigen::Vector3f p = project_to_window(view, posed_position(d, i));
        x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
        ++tip;
    }
    ASSERT_GT(tip, 0u);
    const double dpr = front->devicePixelRatioF();
    const int h = view.height;
    const QPoint from(int((x0 - 3) / dpr), int((h - y1 - 3) / dpr)), to(int((x1 + 3) / dpr) + 1, int((h - y0 + 3) / dpr) + 1);
    ASSERT_TRUE(front->rect().contains(from) && front->rect().contains(to)) << "the tip is out of the view";
    drag(front, from, to);
    const std::vector<uint32_t> selected = d.selection();
    ASSERT_FALSE(selected.empty());
    // Core's selection of the posed points in the same rectangle, and only tip samples.
    const PixelRect rect{float(from.x() * dpr), float(h - from.y() * dpr), float(to.x() * dpr), float(h - to.y() * dpr)};
    EXPECT_EQ(selected, samples_in_rect(SamplePoints(d.posed()->sample_points(), d.samples().origin), d.tree(),
                                        d.current(), view, rect));
    for (uint32_t i : selected) {
        EXPECT_GE(posed_position(d, i).y(), 0.3) << "sample " << i << " is not on the standing tip";
        EXPECT_GT(d.samples().position(i).x(), 1.3) << "sample " << i << " is not of the tip half";
    }
    // At the bind pose those samples lie along the bar, outside the rectangle.
    EXPECT_TRUE(samples_in_rect(d.samples(), d.tree(), d.current(), view, rect).empty());
    EXPECT_EQ(d.strokes_pose(), (RecipePose{"step", 1.0}));
    // The window as docs/editor.md shows it.
    w.grab().save(QString::fromStdString(editor_output_dir() + "/timeline.png"));
}

TEST_F(Timeline, ASplitMadeWhilePosedRecordsThePoseAndUndoesAndRedoes) {
    editor::MainWindow& w = this->w();
    const std::vector<uint8_t> opened = w.document().encode();
    choose_clip(w, "step");
    slide_to(w, 10);
    ASSERT_TRUE(frame_all(w));
    editor::ViewWidget* front = w.grid().view(1);
    // The upper half of the front view: the standing tip.
    drag(front, QPoint(1, 1), QPoint(front->width() - 1, front->height() / 2 - 10));
    const std::vector<uint32_t> selected = w.document().selection();
    ASSERT_FALSE(selected.empty());
    ASSERT_LT(selected.size(), w.document().samples().size());
    EXPECT_EQ(w.undo_stack().count(), 0) << "posing is not an edit";
    QTest::keyClick(front, Qt::Key_S);
    ASSERT_EQ(w.undo_stack().count(), 1) << w.last_message().toStdString();
    EXPECT_NE(w.undo_stack().text(0).indexOf("at step 1.000 s"), -1) << w.undo_stack().text(0).toStdString();
    const SamplingTree split = w.document().tree();
    ASSERT_EQ(split.recipe().size(), 1u);
    EXPECT_EQ(split.recipe().front().pose, (RecipePose{"step", 1.0}));
    EXPECT_EQ(split.find(2)->samples, selected);
    const std::vector<uint8_t> after = w.document().encode();
    const std::vector<QImage> split_picture = pictures(w);

    QTest::keyClick(front, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(w.document().encode(), opened);
    EXPECT_TRUE(w.document().tree().find(root_id())->active);
    // Undo keeps the pose: the views still show the clip at 1 s.
    EXPECT_EQ(w.document().pose().clip(), 1); // "step", the second clip
    EXPECT_DOUBLE_EQ(w.document().pose().time(), 1.0);
    ASSERT_NE(w.document().posed(), nullptr);
    QTest::keyClick(front, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(w.document().encode(), after);
    const std::vector<QImage> redone = pictures(w);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(redone[size_t(i)] == split_picture[size_t(i)]) << "view " << i;

    // Saved, the step keeps its pose (.spt version 4).
    ASSERT_TRUE(w.save_to(QString::fromStdString(dir_.file("posed.spt"))));
    const SptDocument saved = load_spt(dir_.file("posed.spt"));
    EXPECT_EQ(spt_version_for(saved), 4u);
    EXPECT_EQ(saved.trees.front().recipe().front().pose, (RecipePose{"step", 1.0}));
}

TEST_F(Timeline, RectanglesAtTwoPosesRecordNoStep) {
    editor::MainWindow& w = this->w();
    editor::ViewWidget* front = w.grid().view(1);
    drag(front, QPoint(1, 1), QPoint(front->width() / 2, front->height() - 1));
    EXPECT_EQ(w.document().strokes().size(), 1u);
    choose_clip(w, "linear");
    slide_to(w, 5);
    drag(front, QPoint(1, 1), QPoint(front->width() / 4, front->height() - 1), Qt::ControlModifier);
    // One step holds one pose: the selection stays, its strokes are not recorded.
    EXPECT_TRUE(w.document().strokes().empty());
    ASSERT_TRUE(w.split()) << w.last_message().toStdString();
    EXPECT_TRUE(w.document().tree().recipe().empty());
}

TEST_F(Timeline, PlayRunsUntilPausedAndTheDocumentClosingStopsIt) {
    editor::MainWindow& w = this->w();
    save();
    choose_clip(w, "linear");
    QPushButton* play = w.timeline().play_button();
    QSignalSpy posed(&w.document(), &editor::EditorDocument::poseChanged);
    QTest::mouseClick(play, Qt::LeftButton);
    EXPECT_TRUE(w.timeline().playing());
    EXPECT_EQ(play->text(), "Pause");
    // Timeouts are hang guards, not performance limits.
    ASSERT_TRUE(posed.wait(60000));
    ASSERT_TRUE(posed.wait(60000));
    EXPECT_GT(w.document().pose().time(), 0.0);
    QTest::mouseClick(play, Qt::LeftButton);
    EXPECT_FALSE(w.timeline().playing());
    EXPECT_EQ(play->text(), "Play");
    const double paused_at = w.document().pose().time();
    posed.clear();
    QTest::qWait(300);
    EXPECT_EQ(posed.count(), 0);
    EXPECT_EQ(w.document().pose().time(), paused_at);
    EXPECT_EQ(w.undo_stack().count(), 0) << "playing is not an edit";

    // Playing again, then the window closes: the timer stops with the document.
    QSignalSpy stopped(&w.timeline(), &editor::TimelineBar::playingChanged);
    QTest::mouseClick(play, Qt::LeftButton);
    ASSERT_TRUE(w.timeline().playing());
    ASSERT_TRUE(w.close());
    EXPECT_FALSE(w.timeline().playing());
    ASSERT_EQ(stopped.count(), 2);
    EXPECT_FALSE(stopped.at(1).at(0).toBool());
}

TEST_F(Timeline, OpeningAnotherFileStopsPlayingAndHidesTheTimeline) {
    editor::MainWindow& w = this->w();
    save();
    choose_clip(w, "cubic");
    QTest::mouseClick(w.timeline().play_button(), Qt::LeftButton);
    ASSERT_TRUE(w.timeline().playing());
    w.open_file(write_editor_files(dir_).spt);
    ASSERT_TRUE(wait_ready(w));
    EXPECT_FALSE(w.timeline().playing());
    EXPECT_FALSE(w.timeline().isVisible());
    EXPECT_EQ(w.document().posed(), nullptr);
    // And the saved bar, opened again with its mesh beside it: its clips are back, at the bind pose.
    std::filesystem::copy_file(kBar.toStdString(), dir_.file("bending_bar.gltf"));
    w.open_file(QString::fromStdString(dir_.file("bar.spt")));
    ASSERT_TRUE(wait_ready(w));
    EXPECT_TRUE(w.timeline().isVisible());
    EXPECT_EQ(w.timeline().clips()->currentIndex(), 0);
}

} // namespace

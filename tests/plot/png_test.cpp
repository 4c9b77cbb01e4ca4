// PNG output: the file holds the rendered pixels, is the same every time, and failures are reported.
#include "spt/plot/chart.hpp"
#include <QFile>
#include <QImage>
#include <filesystem>
#include <gtest/gtest.h>

using namespace spt::plot;

namespace {

std::string temp_dir(const std::string& name) {
    const std::string d = std::string(SPT_BINARY_DIR) + "/test-output/plot/" + name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

Chart small_chart() {
    Chart c;
    c.title = "PNG";
    c.x.scale = Scale::Log10;
    Series s;
    s.name = "points", s.colour = QColor(40, 100, 220), s.points = {{10, 1}, {1000, 3}, {50, 2}};
    c.series.push_back(s);
    return c;
}

QByteArray read_all(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

TEST(plot_png, written_file_holds_the_rendered_pixels) {
    const QString path = QString::fromStdString(temp_dir("roundtrip") + "/chart.png");
    QString error;
    ASSERT_TRUE(save_chart_png(small_chart(), path, QSize(480, 320), 2, &error)) << error.toStdString();
    QImage back(path);
    ASSERT_FALSE(back.isNull());
    const QImage want = render_chart(small_chart(), QSize(480, 320), 2);
    EXPECT_EQ(back.size(), QSize(960, 640));
    EXPECT_EQ(back.convertToFormat(QImage::Format_RGB32), want.convertToFormat(QImage::Format_RGB32));
}

TEST(plot_png, same_chart_gives_the_same_file_bytes) {
    const std::string d = temp_dir("bytes");
    const QString a = QString::fromStdString(d + "/a.png"), b = QString::fromStdString(d + "/b.png");
    ASSERT_TRUE(save_chart_png(small_chart(), a, QSize(480, 320)));
    ASSERT_TRUE(save_chart_png(small_chart(), b, QSize(480, 320)));
    const QByteArray x = read_all(a);
    EXPECT_GT(x.size(), 1000);
    EXPECT_EQ(x, read_all(b));
}

TEST(plot_png, write_into_a_missing_folder_reports_failure_naming_the_path) {
    const QString path = QString::fromStdString(temp_dir("missing") + "/no/such/folder/chart.png");
    QString error;
    EXPECT_FALSE(save_chart_png(small_chart(), path, QSize(200, 100), 1, &error));
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
    EXPECT_FALSE(QFile::exists(path));
}

TEST(plot_png, write_over_a_folder_reports_failure) {
    const std::string d = temp_dir("folder");
    std::filesystem::create_directories(d + "/chart.png");
    QString error;
    EXPECT_FALSE(save_chart_png(small_chart(), QString::fromStdString(d + "/chart.png"), QSize(200, 100), 1, &error));
    EXPECT_FALSE(error.isEmpty());
    EXPECT_TRUE(std::filesystem::is_directory(d + "/chart.png"));
}

TEST(plot_png, absurd_size_reports_failure_and_keeps_the_old_file) {
    const QString path = QString::fromStdString(temp_dir("absurd") + "/chart.png");
    ASSERT_TRUE(save_chart_png(small_chart(), path, QSize(200, 100)));
    const QByteArray before = read_all(path);
    QString error;
    EXPECT_FALSE(save_chart_png(small_chart(), path, QSize(200000, 100), 1, &error));
    EXPECT_TRUE(error.contains("too large")) << error.toStdString();
    EXPECT_EQ(read_all(path), before);
}

// The locomotives' pictures on the desk: a throttle and the loco editor show the station's picture of
// their locomotive, or a placeholder that says why there is none; a picture cut off because the station
// went away is never shown, and the whole one appears once the station is back.

#include "EmbeddedStationSupport.h"
#include "FakeWebServer.h"
#include "binding/RailwayBinding.h"
#include "common/LocomotivePictureBook.h"
#include "locomotives/LocomotiveFileModel.h"
#include "locomotives/LocomotiveForm.h"
#include "model/Railway.h"
#include "shell/Translations.h"
#include "sim/StationLayout.h"
#include "support/StationTestSupport.h"
#include "throttle/ThrottleWidget.h"

#include <QLabel>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr int WaitMs = 10000;
constexpr quint32 Br218 = 0x4001; // .icon=BR 218
const QSize ThrottlePicture(132, 44);

QImage demoPicture(const char* name) {
    static const sim::StationLayout demo = sim::StationLayout::demo();
    return QImage::fromData(QByteArray::fromStdString(demo.pictureFor(name).value_or(std::string())), "PNG");
}

QByteArray demoBytes(const char* name) {
    static const sim::StationLayout demo = sim::StationLayout::demo();
    return QByteArray::fromStdString(demo.pictureFor(name).value_or(std::string()));
}

bool showsPicture(const QLabel* label) {
    return !label->property("placeholder").toBool();
}

QImage shown(const QLabel* label) {
    return label->pixmap().toImage().convertToFormat(QImage::Format_ARGB32);
}

// Pixels whose premultiplied colour or alpha differ by more than 3 in any channel (what is seen: the
// colour of a transparent pixel is not).
int differingPixels(const QImage& first, const QImage& second) {
    if (first.size() != second.size())
        return first.width() * first.height() + 1;
    const QImage a = first.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    const QImage b = second.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y);
            const QRgb q = b.pixel(x, y);
            differing += std::abs(qRed(p) - qRed(q)) > 3 || std::abs(qGreen(p) - qGreen(q)) > 3 ||
                         std::abs(qBlue(p) - qBlue(q)) > 3 || std::abs(qAlpha(p) - qAlpha(q)) > 3;
        }
    return differing;
}

class DeskPictures : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        QObject::connect(&railways, &binding::RailwayBinding::railwayChanged, &throttle,
                         &ThrottleWidget::setRailway);
        connection.connectToSimulator();
        ASSERT_TRUE(test::waitForState(connection, State::Ready));
        throttle.show();
    }

    Translations translations;
    connection::StationConnection connection{support::withEmbeddedStation()};
    binding::RailwayBinding railways{connection};
    ThrottleWidget throttle;
};

} // namespace

TEST_F(DeskPictures, AThrottleShowsTheStationsPictureOfItsLocomotive) {
    LocomotivePictureBook book(&connection.pictures());
    throttle.setPictures(&book);
    throttle.setLocomotive(Br218);
    EXPECT_FALSE(showsPicture(throttle.picture())) << "the placeholder while the picture loads";
    EXPECT_EQ(throttle.picture()->toolTip(), "Loading the picture “BR 218”…");
    ASSERT_TRUE(QTest::qWaitFor([&] { return showsPicture(throttle.picture()); }, WaitMs));
    const QImage expected = demoPicture("BR 218.png")
                                .scaled(ThrottlePicture, Qt::KeepAspectRatio, Qt::SmoothTransformation)
                                .convertToFormat(QImage::Format_ARGB32);
    EXPECT_EQ(shown(throttle.picture()).size(), ThrottlePicture);
    // Equal up to the rounding of semi-transparent edges on the way through a pixmap.
    EXPECT_EQ(differingPixels(shown(throttle.picture()), expected), 0);
    const QImage other = demoPicture("ICE 3.png")
                             .scaled(ThrottlePicture, Qt::KeepAspectRatio, Qt::SmoothTransformation)
                             .convertToFormat(QImage::Format_ARGB32);
    EXPECT_GT(differingPixels(shown(throttle.picture()), other), 1000) << "another loco's picture differs";
    EXPECT_EQ(throttle.picture()->toolTip(), "Picture “BR 218”");
    EXPECT_EQ(throttle.findChild<QLabel*>("locomotiveDetails")->text(), "MFX 1");
}

TEST_F(DeskPictures, WithoutAStationToAskTheThrottleShowsThePlaceholderAndSaysWhy) {
    connection::LocomotivePictures nowhere;
    LocomotivePictureBook book(&nowhere);
    throttle.setPictures(&book);
    throttle.setLocomotive(Br218);
    EXPECT_FALSE(showsPicture(throttle.picture()));
    EXPECT_EQ(
        shown(throttle.picture()),
        LocomotivePictureBook::placeholder(ThrottlePicture).toImage().convertToFormat(QImage::Format_ARGB32));
    EXPECT_EQ(throttle.picture()->toolTip(), "No picture “BR 218”: no station to ask and no icons folder");

    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(throttle.picture()->toolTip(),
              "Kein Bild „BR 218“: keine Zentrale zum Fragen und kein Bilderordner");
    ASSERT_TRUE(translations.select(Language::English));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

// The station is switched off while it sends the picture, and is back a second later.
TEST_F(DeskPictures, APictureCutOffMidwayIsNeverShownAndAppearsWhenTheStationIsBack) {
    support::FakeWebServer web;
    web.add("BR 218.png", demoBytes("BR 218.png"));
    web.setMode(support::FakeWebServer::Mode::CutMidBody);
    connection::LocomotivePictures pictures;
    pictures.setStation(web.address());
    LocomotivePictureBook book(&pictures);
    throttle.setPictures(&book);
    throttle.setLocomotive(Br218);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return pictures.status("BR 218") == connection::LocomotivePictures::Status::Failed; }, WaitMs));
    EXPECT_FALSE(showsPicture(throttle.picture()));
    EXPECT_EQ(
        throttle.picture()->toolTip(),
        "No picture “BR 218”: the station did not send it; asked again when it is back\nLooked for at " +
            web.address() + "/icons/BR 218.png");

    web.stop();
    QTest::qWait(1000);
    EXPECT_FALSE(showsPicture(throttle.picture()));
    web.setMode(support::FakeWebServer::Mode::Serve);
    ASSERT_TRUE(web.start());
    pictures.retryFailed(); // what the connection does when its start-up finds the station again
    ASSERT_TRUE(QTest::qWaitFor([&] { return showsPicture(throttle.picture()); }, WaitMs));
    EXPECT_EQ(throttle.picture()->toolTip(), "Picture “BR 218”");
    EXPECT_EQ(web.requests(), 2);
}

TEST_F(DeskPictures, TheLocoEditorAndListShowThePicture) {
    LocomotivePictureBook book(&connection.pictures());
    LocomotiveForm form;
    form.setPictures(&book);
    form.setIcon("ICE 3");
    form.show();
    EXPECT_EQ(form.pictureName()->text(), "ICE 3");
    ASSERT_TRUE(QTest::qWaitFor([&] { return book.hasPicture("ICE 3"); }, WaitMs));
    EXPECT_EQ(form.picture()->pixmap().size(), QSize(132, 44));
    EXPECT_EQ(form.picture()->toolTip(), "Picture “ICE 3”");
    form.setIcon({});
    EXPECT_EQ(form.pictureName()->text(), "none");
    EXPECT_EQ(form.picture()->toolTip(), "This locomotive names no picture");

    cs2config::LocomotiveFile file;
    file.locomotives.resize(1);
    file.locomotives[0].name = "ICE 3 Velaro";
    file.locomotives[0].icon = "ICE 3";
    file.locomotives[0].uid = 0x4002;
    const cs2config::LocomotiveEditor editor(file);
    LocomotiveFileModel model;
    model.show(&editor);
    model.setPictures(&book);
    ASSERT_EQ(model.rowCount(), 1);
    const QModelIndex icon = model.index(0, LocomotiveFileModel::Icon);
    const QPixmap small = model.data(icon, Qt::DecorationRole).value<QPixmap>();
    EXPECT_EQ(small.size(), LocomotiveFileModel::PictureBox);
    EXPECT_EQ(small.toImage().convertToFormat(QImage::Format_ARGB32),
              demoPicture("ICE 3.png")
                  .scaled(LocomotiveFileModel::PictureBox, Qt::KeepAspectRatio, Qt::SmoothTransformation)
                  .convertToFormat(QImage::Format_ARGB32));
    EXPECT_EQ(model.data(icon, Qt::ToolTipRole).toString(), "Picture “ICE 3”");
    EXPECT_EQ(model.data(icon, Qt::DisplayRole).toString(), "") << "the picture takes the name's room";
    EXPECT_EQ(model.data(icon, Qt::AccessibleTextRole).toString(), "ICE 3");
}

// The headless platform plugin: contexts, FBOs, sharing and QOpenGLWidget must all work
// with no display server, and without Qt complaining, on each backend (EGL with no
// surface, OSMesa). CTest runs this once per platform name: headless, egl, osmesa.
#include "HeadlessTestMain.h"

#include <QtGui/QOffscreenSurface>
#include <QtGui/QOpenGLContext>
#include <QtGui/QOpenGLFunctions>
#include <QtGui/QScreen>
#include <QtGui/QWindow>
#include <QtOpenGL/QOpenGLFramebufferObject>
#include <QtOpenGL/QOpenGLFunctions_3_3_Core>
#include <QtOpenGL/QOpenGLVersionFunctionsFactory>
#include <QtOpenGLWidgets/QOpenGLWidget>
#include <QtWidgets/QMainWindow>

#include <array>
#include <cstring>
#include <memory>
#include <optional>

namespace {

// Colour channels may be off by a rounding step after float -> 8-bit conversion.
constexpr int colourTolerance = 2;

// Empty when `actual` matches `expected` within the tolerance, else a message saying how.
QString colourMismatch(QColor actual, QColor expected, const QString &where)
{
    const bool near = qAbs(actual.red() - expected.red()) <= colourTolerance
            && qAbs(actual.green() - expected.green()) <= colourTolerance
            && qAbs(actual.blue() - expected.blue()) <= colourTolerance;
    if (near)
        return QString();
    return QStringLiteral("%1: got %2, expected %3")
            .arg(where, actual.name(QColor::HexArgb), expected.name(QColor::HexArgb));
}

// Checks the corners and centre of `area` in `image`; empty if all have `expected`.
QString areaMismatch(const QImage &image, const QRect &area, QColor expected)
{
    const std::array<QPoint, 5> points = { area.topLeft(), area.topRight(), area.bottomLeft(),
                                           area.bottomRight(), area.center() };
    for (const QPoint &point : points) {
        if (!image.rect().contains(point))
            return QStringLiteral("point (%1,%2) outside the %3x%4 image")
                    .arg(point.x()).arg(point.y()).arg(image.width()).arg(image.height());
        const QString mismatch = colourMismatch(image.pixelColor(point), expected,
                                                QStringLiteral("pixel (%1,%2)").arg(point.x()).arg(point.y()));
        if (!mismatch.isEmpty())
            return mismatch;
    }
    return QString();
}

QSurfaceFormat formatFor(int major, int minor, QSurfaceFormat::OpenGLContextProfile profile)
{
    QSurfaceFormat format;
    format.setVersion(major, minor);
    format.setProfile(profile);
    return format;
}

// A context current on its own offscreen surface, for tests that need GL and nothing else.
struct OffscreenGL
{
    QOffscreenSurface surface;
    QOpenGLContext context;

    bool create(const QSurfaceFormat &format, QOpenGLContext *shareWith = nullptr)
    {
        surface.setFormat(format);
        surface.create();
        context.setFormat(format);
        context.setShareContext(shareWith);
        return surface.isValid() && context.create() && context.makeCurrent(&surface);
    }
};

// Clears to one colour, so whatever shows it can be checked pixel by pixel.
class ClearingGLWidget : public QOpenGLWidget
{
public:
    explicit ClearingGLWidget(QColor colour, QWidget *parent = nullptr)
        : QOpenGLWidget(parent)
        , m_colour(colour)
    {
    }

    int frames() const { return m_frames; }

protected:
    void paintGL() override
    {
        QOpenGLFunctions *f = context()->functions();
        f->glClearColor(m_colour.redF(), m_colour.greenF(), m_colour.blueF(), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        ++m_frames;
    }

private:
    QColor m_colour;
    int m_frames = 0;
};

// Restores an environment variable when the test ends, whatever happened.
class EnvironmentGuard
{
public:
    explicit EnvironmentGuard(const char *name)
        : m_name(name)
    {
        if (qEnvironmentVariableIsSet(name))
            m_value = qgetenv(name);
    }
    ~EnvironmentGuard()
    {
        if (m_value)
            qputenv(m_name, *m_value);
        else
            qunsetenv(m_name);
    }
    EnvironmentGuard(const EnvironmentGuard &) = delete;
    EnvironmentGuard &operator=(const EnvironmentGuard &) = delete;

private:
    const char *m_name;
    std::optional<QByteArray> m_value;
};

void setOrUnset(const char *name, const QByteArray &value)
{
    if (value.isNull())
        qunsetenv(name);
    else
        qputenv(name, value);
}

} // namespace

class tst_HeadlessPlatform : public QObject
{
    Q_OBJECT

public:
    // The app shares GL resources between widgets (DESIGN.md); test the same setup.
    static void initMain() { QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts); }

private slots:
    void initTestCase();
    void init();

    void selectsPlatformOnlyWhenNothingElseIsConfigured_data();
    void selectsPlatformOnlyWhenNothingElseIsConfigured();

    void backendIsTheOneAskedFor();

    void coreContextProvidesFunctions33();
    void contextReportsCreatedFormat_data();
    void contextReportsCreatedFormat();
    void framebufferObjectReadsBackClearColour_data();
    void framebufferObjectReadsBackClearColour();
    void sharedContextsSeeTheSameTexture();
    void windowShowsSwappedFrameUpright();

    void openGLWidgetShowsItsFrame_data();
    void openGLWidgetShowsItsFrame();
    void openGLWidgetSurvivesZeroSizeAndDestruction();
};

void tst_HeadlessPlatform::initTestCase()
{
    QVERIFY2(shadowlab::headlessPlatformNames().contains(QGuiApplication::platformName()),
             qPrintable(QGuiApplication::platformName()));
    QVERIFY(QGuiApplication::primaryScreen());
    QCOMPARE(QGuiApplication::primaryScreen()->size(), QSize(1920, 1080));
    QCOMPARE(QGuiApplication::primaryScreen()->logicalDotsPerInch(), 96.0);
}

void tst_HeadlessPlatform::init()
{
    // Any warning is a failure: "QOpenGLWidget: Failed to make context current",
    // QRhi creation failures and the like are exactly what this plugin must avoid.
    QTest::failOnWarning(QRegularExpression(QStringLiteral(".*")));
}

void tst_HeadlessPlatform::selectsPlatformOnlyWhenNothingElseIsConfigured_data()
{
    // A null QByteArray means "unset".
    QTest::addColumn<QByteArray>("platform");
    QTest::addColumn<QByteArray>("display");
    QTest::addColumn<QByteArray>("waylandDisplay");
    QTest::addColumn<QByteArray>("expected");

    QTest::newRow("nothing set") << QByteArray() << QByteArray() << QByteArray() << QByteArray("headless");
    QTest::newRow("empty display") << QByteArray() << QByteArray("") << QByteArray() << QByteArray("headless");
    QTest::newRow("X display") << QByteArray() << QByteArray(":0") << QByteArray() << QByteArray();
    QTest::newRow("Wayland display") << QByteArray() << QByteArray() << QByteArray("wayland-0") << QByteArray();
    QTest::newRow("explicit platform") << QByteArray("offscreen") << QByteArray() << QByteArray()
                                       << QByteArray("offscreen");
}

void tst_HeadlessPlatform::selectsPlatformOnlyWhenNothingElseIsConfigured()
{
    QFETCH(QByteArray, platform);
    QFETCH(QByteArray, display);
    QFETCH(QByteArray, waylandDisplay);
    QFETCH(QByteArray, expected);

    const EnvironmentGuard platformGuard("QT_QPA_PLATFORM");
    const EnvironmentGuard displayGuard("DISPLAY");
    const EnvironmentGuard waylandGuard("WAYLAND_DISPLAY");
    setOrUnset("QT_QPA_PLATFORM", platform);
    setOrUnset("DISPLAY", display);
    setOrUnset("WAYLAND_DISPLAY", waylandDisplay);

    shadowlab::selectPlatformForHeadlessUse();

    QCOMPARE(qgetenv("QT_QPA_PLATFORM"), expected);
}

void tst_HeadlessPlatform::backendIsTheOneAskedFor()
{
    // "headless" takes EGL first; Mesa here has the surfaceless platform, so that is what
    // it must get. "egl" and "osmesa" force their backend.
    const QString platform = QGuiApplication::platformName();
    const QString backend = shadowlab::activeHeadlessBackend();
    // SHADOWLAB_EGL_PLATFORM=device makes EGL take its device path (CTest runs that too).
    const QString eglPlatform = qEnvironmentVariable("SHADOWLAB_EGL_PLATFORM", QStringLiteral("surfaceless"));
    if (platform == u"osmesa")
        QCOMPARE(backend, QStringLiteral("osmesa"));
    else
        QCOMPARE(backend, QStringLiteral("egl-") + eglPlatform);
}

void tst_HeadlessPlatform::coreContextProvidesFunctions33()
{
    OffscreenGL gl;
    QVERIFY(gl.create(formatFor(3, 3, QSurfaceFormat::CoreProfile)));

    auto *f = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_3_3_Core>(&gl.context);
    QVERIFY(f);
    QVERIFY(f->initializeOpenGLFunctions());

    const QByteArray renderer(reinterpret_cast<const char *>(f->glGetString(GL_RENDERER)));
    const QByteArray version(reinterpret_cast<const char *>(f->glGetString(GL_VERSION)));
    qInfo("GL_RENDERER: %s, GL_VERSION: %s", renderer.constData(), version.constData());
    QVERIFY(!renderer.isEmpty());

    GLint major = 0;
    GLint minor = 0;
    GLint profileMask = 0;
    f->glGetIntegerv(GL_MAJOR_VERSION, &major);
    f->glGetIntegerv(GL_MINOR_VERSION, &minor);
    f->glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
    QVERIFY2(qMakePair(major, minor) >= qMakePair(3, 3), version.constData());
    QVERIFY(profileMask & GL_CONTEXT_CORE_PROFILE_BIT);
    QCOMPARE(f->glGetError(), GLenum(GL_NO_ERROR));

    const QSurfaceFormat format = gl.context.format();
    QCOMPARE(format.profile(), QSurfaceFormat::CoreProfile);
    QCOMPARE(format.version(), qMakePair(int(major), int(minor)));
    QCOMPARE(format.redBufferSize(), 8);
    QCOMPARE(format.alphaBufferSize(), 8);
    QCOMPARE(format.depthBufferSize(), 24);
    QCOMPARE(format.stencilBufferSize(), 8);
    QCOMPARE(gl.context.defaultFramebufferObject(), GLuint(0));
    gl.context.doneCurrent();
    QCOMPARE(QOpenGLContext::currentContext(), nullptr);
}

void tst_HeadlessPlatform::contextReportsCreatedFormat_data()
{
    QTest::addColumn<QSurfaceFormat>("requested");
    QTest::addColumn<QSurfaceFormat::OpenGLContextProfile>("expectedProfile");
    QTest::addColumn<int>("minimumMajor");
    QTest::addColumn<int>("minimumMinor");

    using P = QSurfaceFormat;
    // A default format asks for 2.0 without a profile; the renderer needs 3.3 core.
    QTest::newRow("default") << QSurfaceFormat() << P::CoreProfile << 3 << 3;
    QTest::newRow("3.2, no profile") << formatFor(3, 2, P::NoProfile) << P::CoreProfile << 3 << 3;
    QTest::newRow("3.3 core") << formatFor(3, 3, P::CoreProfile) << P::CoreProfile << 3 << 3;
    QTest::newRow("4.1 core") << formatFor(4, 1, P::CoreProfile) << P::CoreProfile << 4 << 1;
    QTest::newRow("explicit compatibility") << formatFor(3, 0, P::CompatibilityProfile) << P::CompatibilityProfile
                                            << 3 << 0;
}

void tst_HeadlessPlatform::contextReportsCreatedFormat()
{
    QFETCH(QSurfaceFormat, requested);
    QFETCH(QSurfaceFormat::OpenGLContextProfile, expectedProfile);
    QFETCH(int, minimumMajor);
    QFETCH(int, minimumMinor);

    OffscreenGL gl;
    QVERIFY(gl.create(requested));
    QOpenGLFunctions *f = gl.context.functions();
    GLint major = 0;
    GLint minor = 0;
    GLint profileMask = 0;
    f->glGetIntegerv(GL_MAJOR_VERSION, &major);
    f->glGetIntegerv(GL_MINOR_VERSION, &minor);
    f->glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);

    QVERIFY2(qMakePair(int(major), int(minor)) >= qMakePair(minimumMajor, minimumMinor),
             qPrintable(QStringLiteral("%1.%2").arg(major).arg(minor)));
    QCOMPARE(gl.context.format().version(), qMakePair(int(major), int(minor)));
    QCOMPARE(gl.context.format().profile(), expectedProfile);
    const GLint expectedBit = expectedProfile == QSurfaceFormat::CoreProfile ? GL_CONTEXT_CORE_PROFILE_BIT
                                                                             : GL_CONTEXT_COMPATIBILITY_PROFILE_BIT;
    QVERIFY(profileMask & expectedBit);
}

void tst_HeadlessPlatform::framebufferObjectReadsBackClearColour_data()
{
    QTest::addColumn<QColor>("colour");
    QTest::newRow("red") << QColor(255, 0, 0);
    QTest::newRow("slate") << QColor(51, 102, 153);
    QTest::newRow("near white") << QColor(250, 240, 230);
}

void tst_HeadlessPlatform::framebufferObjectReadsBackClearColour()
{
    QFETCH(QColor, colour);

    OffscreenGL gl;
    QVERIFY(gl.create(formatFor(3, 3, QSurfaceFormat::CoreProfile)));
    QOpenGLFramebufferObject fbo(QSize(64, 32));
    QVERIFY(fbo.isValid());
    QVERIFY(fbo.bind());
    QOpenGLFunctions *f = gl.context.functions();
    f->glViewport(0, 0, 64, 32);
    f->glClearColor(colour.redF(), colour.greenF(), colour.blueF(), 1.0f);
    f->glClear(GL_COLOR_BUFFER_BIT);

    const QImage image = fbo.toImage();
    QCOMPARE(image.size(), QSize(64, 32));
    const QString mismatch = areaMismatch(image, image.rect(), colour);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void tst_HeadlessPlatform::sharedContextsSeeTheSameTexture()
{
    const QColor colour(200, 100, 50);
    const QSurfaceFormat format = formatFor(3, 3, QSurfaceFormat::CoreProfile);

    OffscreenGL creator;
    QVERIFY(creator.create(format));
    OffscreenGL reader;
    QVERIFY(reader.create(format, &creator.context));
    QVERIFY(QOpenGLContext::areSharing(&creator.context, &reader.context));
    QCOMPARE(reader.context.shareContext(), &creator.context);

    // Upload a solid 4x4 texture in the first context...
    QVERIFY(creator.context.makeCurrent(&creator.surface));
    QOpenGLFunctions *cf = creator.context.functions();
    const std::array<quint32, 16> texels = [&] {
        std::array<quint32, 16> t;
        const uchar rgba[4] = { uchar(colour.red()), uchar(colour.green()), uchar(colour.blue()), 255 };
        quint32 texel;
        std::memcpy(&texel, rgba, sizeof texel);
        t.fill(texel);
        return t;
    }();
    GLuint texture = 0;
    cf->glGenTextures(1, &texture);
    cf->glBindTexture(GL_TEXTURE_2D, texture);
    cf->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    cf->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    cf->glFinish();

    // ...and read it in the second through an FBO of its own (FBOs are not shared).
    QVERIFY(reader.context.makeCurrent(&reader.surface));
    QOpenGLFunctions *rf = reader.context.functions();
    QVERIFY(rf->glIsTexture(texture));
    GLuint fbo = 0;
    rf->glGenFramebuffers(1, &fbo);
    rf->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    rf->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    QCOMPARE(rf->glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    std::array<uchar, 4> pixel{};
    rf->glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
    rf->glBindFramebuffer(GL_FRAMEBUFFER, reader.context.defaultFramebufferObject());
    rf->glDeleteFramebuffers(1, &fbo);
    QCOMPARE(rf->glGetError(), GLenum(GL_NO_ERROR));

    const QString mismatch = colourMismatch(QColor(pixel[0], pixel[1], pixel[2]), colour, QStringLiteral("texel"));
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    QVERIFY(creator.context.makeCurrent(&creator.surface));
    cf->glDeleteTextures(1, &texture);
}

void tst_HeadlessPlatform::windowShowsSwappedFrameUpright()
{
    const QColor top(255, 0, 0);
    const QColor bottom(0, 0, 255);
    auto window = std::make_unique<QWindow>();
    window->setSurfaceType(QSurface::OpenGLSurface);
    window->resize(60, 40);
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    QOpenGLContext context;
    context.setFormat(window->requestedFormat());
    QVERIFY(context.create());

    // Top half and bottom half in different colours, so a frame shown upside down
    // (OSMesa's rows run bottom-up) cannot pass.
    const auto drawAndCheck = [&](QSize size) -> QString {
        if (!context.makeCurrent(window.get()))
            return QStringLiteral("makeCurrent failed");
        QOpenGLFunctions *f = context.functions();
        f->glViewport(0, 0, size.width(), size.height());
        f->glClearColor(bottom.redF(), bottom.greenF(), bottom.blueF(), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        f->glEnable(GL_SCISSOR_TEST);
        f->glScissor(0, size.height() / 2, size.width(), size.height() / 2); // GL's y axis points up
        f->glClearColor(top.redF(), top.greenF(), top.blueF(), 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        f->glDisable(GL_SCISSOR_TEST);
        context.swapBuffers(window.get());

        const QImage shown = window->screen()->grabWindow(window->winId()).toImage();
        if (shown.size() != size)
            return QStringLiteral("presented %1x%2").arg(shown.width()).arg(shown.height());
        const int half = size.height() / 2;
        QString mismatch = areaMismatch(shown, QRect(0, 0, size.width(), half), top);
        if (mismatch.isEmpty())
            mismatch = areaMismatch(shown, QRect(0, half, size.width(), size.height() - half), bottom);
        return mismatch;
    };
    QString mismatch = drawAndCheck(QSize(60, 40));
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    // The window's GL buffer is reallocated while the context is current on it...
    window->resize(90, 70);
    QTRY_COMPARE(window->size(), QSize(90, 70));
    mismatch = drawAndCheck(QSize(90, 70));
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    // ...and the window goes away while the context is still current on it.
    window.reset();
    QOffscreenSurface surface;
    surface.create();
    QVERIFY(context.makeCurrent(&surface));
    QCOMPARE(context.functions()->glGetError(), GLenum(GL_NO_ERROR));
}

void tst_HeadlessPlatform::openGLWidgetShowsItsFrame_data()
{
    QTest::addColumn<bool>("inMainWindow");
    QTest::newRow("plain top-level widget") << false;
    QTest::newRow("main window") << true;
}

void tst_HeadlessPlatform::openGLWidgetShowsItsFrame()
{
    QFETCH(bool, inMainWindow);
    const QColor colour(40, 180, 90);

    std::unique_ptr<QWidget> topLevel;
    QWidget *parent = nullptr;
    if (inMainWindow) {
        auto window = std::make_unique<QMainWindow>();
        parent = new QWidget;
        window->setCentralWidget(parent);
        topLevel = std::move(window);
    } else {
        topLevel = std::make_unique<QWidget>();
        parent = topLevel.get();
    }
    auto *glWidget = new ClearingGLWidget(colour, parent);
    topLevel->resize(240, 160);
    glWidget->setGeometry(20, 10, 120, 90);
    topLevel->show();
    QVERIFY(QTest::qWaitForWindowExposed(topLevel.get()));
    QTRY_VERIFY(glWidget->frames() > 0);
    QVERIFY(glWidget->isValid());

    // The widget's own framebuffer.
    const QImage frame = glWidget->grabFramebuffer();
    QCOMPARE(frame.size(), glWidget->size());
    QString mismatch = areaMismatch(frame, frame.rect(), colour);
    QVERIFY2(mismatch.isEmpty(), qPrintable(QStringLiteral("grabFramebuffer: ") + mismatch));

    // The whole window rendered by QWidget::grab(): GL colour exactly under the GL widget.
    const QRect glArea(glWidget->mapTo(topLevel.get(), QPoint(0, 0)), glWidget->size());
    const QImage windowImage = topLevel->grab().toImage();
    QCOMPARE(windowImage.size(), topLevel->size());
    mismatch = areaMismatch(windowImage, glArea, colour);
    QVERIFY2(mismatch.isEmpty(), qPrintable(QStringLiteral("QWidget::grab: ") + mismatch));
    QVERIFY(!colourMismatch(windowImage.pixelColor(glArea.topLeft() - QPoint(5, 5)), colour, QString()).isEmpty());

    // What the window presented: Qt composes the GL texture over the raster widgets
    // with QRhi on the window surface and swaps, which the screen grab shows.
    QScreen *screen = topLevel->screen();
    QTRY_VERIFY2((mismatch = areaMismatch(screen->grabWindow(topLevel->winId()).toImage(), glArea, colour)).isEmpty(),
                 qPrintable(QStringLiteral("screen grab: ") + mismatch));
}

void tst_HeadlessPlatform::openGLWidgetSurvivesZeroSizeAndDestruction()
{
    const QColor colour(220, 60, 120);
    QWidget topLevel;
    topLevel.resize(200, 150);
    auto *glWidget = new ClearingGLWidget(colour, &topLevel);
    glWidget->setGeometry(10, 10, 100, 80);
    topLevel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&topLevel));
    QTRY_VERIFY(glWidget->frames() > 0);

    glWidget->resize(0, 0);
    QTest::qWait(50);
    const int framesBefore = glWidget->frames();
    glWidget->resize(100, 80);
    QTRY_VERIFY(glWidget->frames() > framesBefore);
    const QImage frame = glWidget->grabFramebuffer();
    QCOMPARE(frame.size(), QSize(100, 80));
    QString mismatch = areaMismatch(frame, frame.rect(), colour);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    // Resizing the window reallocates the buffer its GL composition draws into. The GL
    // widget changes size too: Qt 6.4 only re-wraps the widget's texture for composition
    // when its size changes, so after the same-size round trip above the window would
    // keep showing a stale texture on any platform.
    topLevel.resize(320, 240);
    glWidget->resize(120, 90);
    QScreen *screen = topLevel.screen();
    QTRY_COMPARE(screen->grabWindow(topLevel.winId()).size(), QSize(320, 240));
    QTRY_VERIFY2((mismatch = areaMismatch(screen->grabWindow(topLevel.winId()).toImage(), glWidget->geometry(),
                                          colour)).isEmpty(),
                 qPrintable(QStringLiteral("screen grab: ") + mismatch));

    delete glWidget;
    QTest::qWait(50);
    topLevel.hide();
    topLevel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&topLevel));
    const QImage windowImage = topLevel.grab().toImage();
    QCOMPARE(windowImage.size(), QSize(320, 240));
    QVERIFY(!colourMismatch(windowImage.pixelColor(50, 50), colour, QString()).isEmpty());
}

SHADOWLAB_TEST_MAIN(tst_HeadlessPlatform)
#include "tst_HeadlessPlatform.moc"

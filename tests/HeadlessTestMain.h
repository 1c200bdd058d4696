#pragma once

#include "HeadlessPlatform.h"

#include <QtTest/QtTest>
#ifdef QT_WIDGETS_LIB
#include <QtWidgets/QApplication>
#define SHADOWLAB_TEST_APPLICATION QApplication
#else
#include <QtGui/QGuiApplication>
#define SHADOWLAB_TEST_APPLICATION QGuiApplication
#endif

// QTEST_MAIN for ShadowLab (a QApplication where the test links widgets, a QGuiApplication
// where it does not): selects the headless platform (unless the
// environment names another) before the QApplication exists, so every test can
// create widgets, windows and GL contexts with no display server. Like QTEST_MAIN
// it calls an optional static TestClass::initMain() first, the place for
// pre-application setup such as Qt::AA_ShareOpenGLContexts.
#define SHADOWLAB_TEST_MAIN(TestClass)                                  \
    int main(int argc, char *argv[])                                    \
    {                                                                   \
        shadowlab::selectPlatformForHeadlessUse();                      \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestClass>(); \
        SHADOWLAB_TEST_APPLICATION app(argc, argv);                                   \
        app.setAttribute(Qt::AA_Use96Dpi, true);                        \
        TestClass tc;                                                   \
        QTEST_SET_MAIN_SOURCE_PATH                                      \
        return QTest::qExec(&tc, argc, argv);                           \
    }

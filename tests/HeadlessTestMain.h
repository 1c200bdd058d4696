#pragma once

#include "HeadlessPlatform.h"

#include <QtTest/QtTest>
#include <QtWidgets/QApplication>

// QTEST_MAIN for ShadowLab: selects the headless platform (unless the
// environment names another) before the QApplication exists, so every test can
// create widgets, windows and GL contexts with no display server. Like QTEST_MAIN
// it calls an optional static TestClass::initMain() first, the place for
// pre-application setup such as Qt::AA_ShareOpenGLContexts.
#define SHADOWLAB_TEST_MAIN(TestClass)                                  \
    int main(int argc, char *argv[])                                    \
    {                                                                   \
        shadowlab::selectPlatformForHeadlessUse();                      \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestClass>(); \
        QApplication app(argc, argv);                                   \
        app.setAttribute(Qt::AA_Use96Dpi, true);                        \
        TestClass tc;                                                   \
        QTEST_SET_MAIN_SOURCE_PATH                                      \
        return QTest::qExec(&tc, argc, argv);                           \
    }

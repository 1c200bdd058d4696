#include "Application.h"
#include "MainWindow.h"
#include "cli/CliSupport.h"
#include "cli/Commands.h"

#include <QApplication>
#include <QGuiApplication>

int main(int argc, char* argv[])
{
    shadowlab::configureApplication();

    QStringList arguments;
    for (int i = 1; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);

    if (!arguments.isEmpty() && shadowlab::cli::isCommand(arguments.first())) {
        // Only commands that build widgets pay for QApplication (styles, fonts, input methods).
        if (shadowlab::cli::needsWidgets(arguments.first())) {
            QApplication app(argc, argv);
            return shadowlab::cli::runCommand(QApplication::arguments().mid(1));
        }
        QGuiApplication app(argc, argv);
        return shadowlab::cli::runCommand(QGuiApplication::arguments().mid(1));
    }
    if (arguments.contains(QStringLiteral("--help")) || arguments.contains(QStringLiteral("-h"))) {
        QGuiApplication app(argc, argv);
        shadowlab::cli::printUsage();
        return shadowlab::cli::kExitOk;
    }
    if (!arguments.isEmpty()) {
        QGuiApplication app(argc, argv);
        shadowlab::cli::err() << "shadowlab: unknown command '" << arguments.first() << "'\n\n";
        shadowlab::cli::printUsage();
        return shadowlab::cli::kExitBadInput;
    }

    QApplication app(argc, argv);
    if (QGuiApplication::platformName() == u"osmesa") {
        // A window nobody can see would run forever: say what to do instead.
        shadowlab::cli::err() << "shadowlab: there is no display, so the explorer cannot open.\n"
                              << "Render it offscreen instead: shadowlab screenshot --out window.png" << Qt::endl;
        return shadowlab::cli::kExitBadInput;
    }
    shadowlab::MainWindow window;
    window.show();
    return app.exec();
}

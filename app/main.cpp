#include "Application.h"
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
        QGuiApplication app(argc, argv);
        return shadowlab::cli::runCommand(QGuiApplication::arguments().mid(1));
    }
    if (arguments.contains(QStringLiteral("--help")) || arguments.contains(QStringLiteral("-h"))) {
        QGuiApplication app(argc, argv);
        shadowlab::cli::printUsage();
        return shadowlab::cli::kExitOk;
    }
    QApplication app(argc, argv);
    shadowlab::cli::printUsage();
    shadowlab::cli::err() << "The explorer window is not built yet; use a command." << Qt::endl;
    return shadowlab::cli::kExitBadInput;
}

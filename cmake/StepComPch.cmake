# Precompiled headers (option STEPCOM_PCH, on by default): the Qt and standard headers most
# sources include, parsed once per set of Qt modules instead of once per source. Only headers
# from outside the project, so a change to our own headers never rebuilds a PCH. Every source
# still includes what it uses: `-DSTEPCOM_PCH=OFF` builds without them (and must keep building).
#
# gcc uses a PCH only where every macro it was made with is defined the same (-Winvalid-pch,
# an error with -Werror, so a mismatch fails the build loudly instead of slowing it). Each PCH
# is therefore made by an empty object library that links just the Qt modules of the targets
# reusing it: they may add definitions of their own, not lack one. An empty target also keeps
# the targets reusing it from waiting for each other.
set(STEPCOM_PCH_CORE <QByteArray> <QCoreApplication> <QDateTime> <QDir> <QElapsedTimer> <QFile>
    <QFileInfo> <QHash> <QJsonArray> <QJsonDocument> <QJsonObject> <QList> <QLocale> <QMap>
    <QObject> <QPointer> <QRegularExpression> <QSet> <QString> <QStringList> <QTimer>
    <QModbusDevice> <QModbusPdu> <QSerialPort> <functional> <memory> <optional> <vector>)
set(STEPCOM_PCH_GUI ${STEPCOM_PCH_CORE} <QColor> <QGuiApplication> <QImage> <QPainter>
    <QTextDocument>)
set(STEPCOM_PCH_WIDGETS ${STEPCOM_PCH_GUI} <QAction> <QApplication> <QCheckBox> <QComboBox>
    <QDialog> <QEvent> <QGridLayout> <QGroupBox> <QHBoxLayout> <QHeaderView> <QLabel>
    <QLineEdit> <QMessageBox> <QPushButton> <QSettings> <QSpinBox> <QStyle> <QTableWidget>
    <QVBoxLayout> <QWidget>)
set(STEPCOM_QT_CORE Qt6::Core Qt6::Network Qt6::SerialBus Qt6::SerialPort)
set(STEPCOM_QT_GUI ${STEPCOM_QT_CORE} Qt6::Gui)
set(STEPCOM_QT_WIDGETS ${STEPCOM_QT_GUI} Qt6::Widgets Qt6::Svg Qt6::Charts)

# stepcom_pch(NAME LIBS qt-targets... HEADERS headers... TARGETS targets...): the PCH target NAME
# (in the calling directory, with its compile definitions), reused by TARGETS.
function(stepcom_pch name)
    if(NOT STEPCOM_PCH)
        return()
    endif()
    cmake_parse_arguments(ARG "" "" "LIBS;HEADERS;TARGETS" ${ARGN})
    file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp CONTENT "// ${name}: a PCH only\n")
    add_library(${name} OBJECT ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp)
    target_link_libraries(${name} PRIVATE ${ARG_LIBS})
    target_precompile_headers(${name} PRIVATE ${ARG_HEADERS})
    foreach(target IN LISTS ARG_TARGETS)
        target_precompile_headers(${target} REUSE_FROM ${name})
    endforeach()
endfunction()

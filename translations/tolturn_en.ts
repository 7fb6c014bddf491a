<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>AdaptiveControl</name>
    <message numerus="yes">
        <source>pass %1 does not exist: the plan has %n pass(es)</source>
        <translation>
            <numerusform>pass %1 does not exist: the plan has %n pass</numerusform>
            <numerusform>pass %1 does not exist: the plan has %n passes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message numerus="yes">
        <source>%n pass(es)</source>
        <translation>
            <numerusform>%n pass</numerusform>
            <numerusform>%n passes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n tolerance(s)</source>
        <translation>
            <numerusform>%n tolerance</numerusform>
            <numerusform>%n tolerances</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n set-up(s): </source>
        <translation>
            <numerusform>; %n set-up: </numerusform>
            <numerusform>; %n set-ups: </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n milled feature(s)</source>
        <translation>
            <numerusform>, %n milled feature</numerusform>
            <numerusform>, %n milled features</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>  roughing: %n pass(es) of ap %1 mm at vc %2 m/min, f %3 mm/rev</source>
        <translation>
            <numerusform>  roughing: %n pass of ap %1 mm at vc %2 m/min, f %3 mm/rev</numerusform>
            <numerusform>  roughing: %n passes of ap %1 mm at vc %2 m/min, f %3 mm/rev</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>wrote %1: %n pass(es)</source>
        <translation>
            <numerusform>wrote %1: %n pass</numerusform>
            <numerusform>wrote %1: %n passes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ControlExample</name>
    <message numerus="yes">
        <source>%n evaluation(s) of the network</source>
        <translation>
            <numerusform>%n evaluation of the network</numerusform>
            <numerusform>%n evaluations of the network</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ImportCommand</name>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MachineLearning</name>
    <message numerus="yes">
        <source>%n stored part(s)</source>
        <translation>
            <numerusform>%n stored part</numerusform>
            <numerusform>%n stored parts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n usable point(s)</source>
        <translation>
            <numerusform>%n usable point</numerusform>
            <numerusform>%n usable points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MeasurementsCommand</name>
    <message numerus="yes">
        <source>stored part %1: %2, %n point(s), in %3</source>
        <translation>
            <numerusform>stored part %1: %2, %n point, in %3</numerusform>
            <numerusform>stored part %1: %2, %n points, in %3</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n point</numerusform>
            <numerusform>%n points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ModelFiles</name>
    <message numerus="yes">
        <source>a %1 model does not take %n coefficient(s)</source>
        <translation>
            <numerusform>a %1 model does not take %n coefficient</numerusform>
            <numerusform>a %1 model does not take %n coefficients</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message numerus="yes">
        <source>%n roughing pass(es) at vc %1 m/min, f %2 mm/rev.</source>
        <translation>
            <numerusform>%n roughing pass at vc %1 m/min, f %2 mm/rev.</numerusform>
            <numerusform>%n roughing passes at vc %1 m/min, f %2 mm/rev.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetupSheet</name>
    <message numerus="yes">
        <source>Program %1 for %2, %n pass(es); spindle limit %3 rpm (%4). Checksum (SHA-256, first 16 digits) of the nominal program %5, of the compensated program %6: compare them with `tolturn-cli gcode` or the G-code tab before running.</source>
        <translation>
            <numerusform>Program %1 for %2, %n pass; spindle limit %3 rpm (%4). Checksum (SHA-256, first 16 digits) of the nominal program %5, of the compensated program %6: compare them with `tolturn-cli gcode` or the G-code tab before running.</numerusform>
            <numerusform>Program %1 for %2, %n passes; spindle limit %3 rpm (%4). Checksum (SHA-256, first 16 digits) of the nominal program %5, of the compensated program %6: compare them with `tolturn-cli gcode` or the G-code tab before running.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::FileController</name>
    <message numerus="yes">
        <source>Opened %1 with %n problem(s) to repair before it can be computed</source>
        <translation>
            <numerusform>Opened %1 with %n problem to repair before it can be computed</numerusform>
            <numerusform>Opened %1 with %n problems to repair before it can be computed</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Report written to %1 (%n page(s))</source>
        <translation>
            <numerusform>Report written to %1 (%n page)</numerusform>
            <numerusform>Report written to %1 (%n pages)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementEntryDialog</name>
    <message numerus="yes">
        <source>%n point(s) read from %1.</source>
        <translation>
            <numerusform>%n point read from %1.</numerusform>
            <numerusform>%n points read from %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementsPanel</name>
    <message numerus="yes">
        <source>%n measured part(s) %1 in %2</source>
        <translation>
            <numerusform>%n measured part %1 in %2</numerusform>
            <numerusform>%n measured parts %1 in %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Part %1 stored with %n point(s).</source>
        <translation>
            <numerusform>Part %1 stored with %n point.</numerusform>
            <numerusform>Part %1 stored with %n points.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n measured part(s) and their points from %1? Models learned before keep what they learned.</source>
        <translation>
            <numerusform>Remove %n measured part and its points from %1? Models learned before keep what they learned.</numerusform>
            <numerusform>Remove %n measured parts and their points from %1? Models learned before keep what they learned.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) removed.</source>
        <translation>
            <numerusform>%n part removed.</numerusform>
            <numerusform>%n parts removed.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) written to %1.</source>
        <translation>
            <numerusform>%n part written to %1.</numerusform>
            <numerusform>%n parts written to %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Measured %1 by %2 (%3), %n point(s) compared.</source>
        <translation>
            <numerusform>Measured %1 by %2 (%3), %n point compared.</numerusform>
            <numerusform>Measured %1 by %2 (%3), %n points compared.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningPanel</name>
    <message numerus="yes">
        <source>Roughing: %n pass(es) at vc %1 m/min, f %2 mm/rev</source>
        <translation>
            <numerusform>Roughing: %n pass at vc %1 m/min, f %2 mm/rev</numerusform>
            <numerusform>Roughing: %n passes at vc %1 m/min, f %2 mm/rev</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProblemNavigator</name>
    <message numerus="yes">
        <source>%n problem(s) stop the computation. Double-click one to go to its value; the results return once all are repaired.</source>
        <translation>
            <numerusform>%n problem stops the computation. Double-click it to go to its value; the results return once it is repaired.</numerusform>
            <numerusform>%n problems stop the computation. Double-click one to go to its value; the results return once all are repaired.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectAnalysis</name>
    <message numerus="yes">
        <source>Not computed: the project has %n problem(s), listed under Problems. Double-click one to go to its value.</source>
        <translation>
            <numerusform>Not computed: the project has %n problem, listed under Problems. Double-click it to go to its value.</numerusform>
            <numerusform>Not computed: the project has %n problems, listed under Problems. Double-click one to go to its value.</numerusform>
        </translation>
    </message>
</context>
</TS>

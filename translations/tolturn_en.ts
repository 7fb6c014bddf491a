<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
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
    <name>tolturn::MainWindow</name>
    <message numerus="yes">
        <source>Not computed: the project has %n problem(s), listed under Problems. Double-click one to go to its value.</source>
        <translation>
            <numerusform>Not computed: the project has %n problem, listed under Problems. Double-click it to go to its value.</numerusform>
            <numerusform>Not computed: the project has %n problems, listed under Problems. Double-click one to go to its value.</numerusform>
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
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>AdaptiveControl</name>
    <message>
        <source>Ra %1 µm</source>
        <translation>Ra %1 µm</translation>
    </message>
    <message>
        <source>Rz %1 µm</source>
        <translation>Rz %1 µm</translation>
    </message>
    <message>
        <source>No feed limit known (the plan&apos;s settings give no feed range): the override&apos;s %1 % alone bounds the feed.</source>
        <translation>Keine Vorschubgrenze bekannt (die Planungsdaten nennen keinen Vorschubbereich): nur die %1 % des Overrides begrenzen den Vorschub.</translation>
    </message>
    <message>
        <source>The feed is held at or below %1 mm/rev, the top of the plan&apos;s feed range (%2).</source>
        <translation>Der Vorschub bleibt bei höchstens %1 mm/U, dem oberen Ende des Vorschubbereichs der Planung (%2).</translation>
    </message>
    <message>
        <source>no source given</source>
        <translation>keine Quelle angegeben</translation>
    </message>
    <message>
        <source>Forces from the project&apos;s %1 model; feed drive 1/(%2 s² + %3 s + 1) (Čuš &amp; Župerl eq. 1), control period %4 ms, feed override %5–%6 %.</source>
        <translation>Kräfte aus dem %1-Modell des Projekts; Vorschubantrieb 1/(%2 s² + %3 s + 1) (Čuš &amp; Župerl Gl. 1), Regeltakt %4 ms, Vorschub-Override %5–%6 %.</translation>
    </message>
    <message>
        <source>Machine noise: %1 % of the force (standard deviation), seed %2.</source>
        <translation>Maschinenrauschen: %1 % der Kraft (Standardabweichung), Startwert %2.</translation>
    </message>
    <message>
        <source>Machine noise: none (the force is measured exactly).</source>
        <translation>Maschinenrauschen: keines (die Kraft wird exakt gemessen).</translation>
    </message>
    <message numerus="yes">
        <source>pass %1 does not exist: the plan has %n pass(es)</source>
        <translation>
            <numerusform>Schnitt %1 gibt es nicht: der Plan hat %n Schnitt</numerusform>
            <numerusform>Schnitt %1 gibt es nicht: der Plan hat %n Schnitte</numerusform>
        </translation>
    </message>
    <message>
        <source>the tool cannot reach the part: it is held over its whole length</source>
        <translation>das Werkzeug erreicht das Teil nicht: es ist auf seiner ganzen Länge gespannt</translation>
    </message>
    <message>
        <source>Pass %1: the feed is held at or below %2 mm/rev for %3 (f² / (32 r_e), f² / (8 r_e)).</source>
        <translation>Schnitt %1: der Vorschub bleibt bei höchstens %2 mm/U für %3 (f² / (32 r_e), f² / (8 r_e)).</translation>
    </message>
    <message>
        <source>pass %1: the adaptive run was stopped after %2 h of cutting short of the end of the pass: the set force asks for a feed the pass hardly advances at</source>
        <translation>Schnitt %1: der adaptive Lauf wurde nach %2 h Schnittzeit vor dem Ende des Schnitts abgebrochen: die Sollkraft verlangt einen Vorschub, bei dem der Schnitt kaum vorankommt</translation>
    </message>
    <message>
        <source>pass %1 cuts up to %2 mm deep where the plan gives %3 mm: the passes before it leave more. The set force is the planned depth&apos;s, so the loop lowers the feed there; plan the passes to the stock</source>
        <translation>Schnitt %1 schneidet bis %2 mm tief, wo der Plan %3 mm vorsieht: die Schnitte davor lassen mehr stehen. Die Sollkraft ist die der geplanten Schnitttiefe, also senkt die Regelung dort den Vorschub; planen Sie die Schnitte passend zum Rohteil</translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>&apos;%1&apos; kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: the data did not reach the disk</source>
        <translation>&apos;%1&apos; kann nicht geschrieben werden: Die Daten haben den Datenträger nicht erreicht</translation>
    </message>
    <message>
        <source>cannot set the permissions of &apos;%1&apos;: %2</source>
        <translation>die Zugriffsrechte von &apos;%1&apos; können nicht gesetzt werden: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>&apos;%1&apos; kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: it is not a regular file (a folder, a device or a pipe)</source>
        <translation>&apos;%1&apos; kann nicht geschrieben werden: es ist keine gewöhnliche Datei (ein Ordner, ein Gerät oder eine Pipe)</translation>
    </message>
</context>
<context>
    <name>BallEndMilling</name>
    <message>
        <source>overhang: %1 mm is not from the ball&apos;s radius, %2 mm, to 1000 mm</source>
        <translation>Auskraglänge: %1 mm liegt nicht zwischen dem Kugelradius, %2 mm, und 1000 mm</translation>
    </message>
    <message>
        <source>equivalent diameter: %1 mm is not above 0 and at most the tool&apos;s %2 mm</source>
        <translation>Ersatzdurchmesser: %1 mm ist nicht größer als 0 und höchstens der Werkzeugdurchmesser %2 mm</translation>
    </message>
    <message>
        <source>Young&apos;s modulus: %1 N/mm² is not positive</source>
        <translation>Elastizitätsmodul: %1 N/mm² ist nicht positiv</translation>
    </message>
    <message>
        <source>holder stiffness k: %1 N/mm is not positive</source>
        <translation>Halter-Steifigkeit k: %1 N/mm ist nicht positiv</translation>
    </message>
    <message>
        <source>holder rotational stiffness k_θ: %1 N·mm/rad is not positive</source>
        <translation>Drehsteifigkeit des Halters k_θ: %1 N·mm/rad ist nicht positiv</translation>
    </message>
    <message>
        <source>tool diameter: %1 mm is not a positive diameter</source>
        <translation>Werkzeugdurchmesser: %1 mm ist kein positiver Durchmesser</translation>
    </message>
    <message>
        <source>flutes: %1 is not 1 to 12</source>
        <translation>Schneiden: %1 liegt nicht zwischen 1 und 12</translation>
    </message>
    <message>
        <source>helix angle: %1° is not 0 to 60°</source>
        <translation>Drallwinkel: %1° liegt nicht zwischen 0 und 60°</translation>
    </message>
    <message>
        <source>feed per tooth: %1 mm is not positive</source>
        <translation>Vorschub je Zahn: %1 mm ist nicht positiv</translation>
    </message>
    <message>
        <source>lead, tilt: %1°, %2° are not within ±60°</source>
        <translation>Anstellwinkel, Kippwinkel: %1°, %2° liegen nicht innerhalb ±60°</translation>
    </message>
    <message>
        <source>radial depth: %1 mm is not positive</source>
        <translation>Radiale Zustellung: %1 mm ist nicht positiv</translation>
    </message>
    <message>
        <source>axial slices: %1 is not 1 to 100000</source>
        <translation>Axiale Scheiben: %1 liegt nicht zwischen 1 und 100000</translation>
    </message>
    <message>
        <source>angles per revolution: %1 is not 1 to 100000</source>
        <translation>Winkel je Umdrehung: %1 liegt nicht zwischen 1 und 100000</translation>
    </message>
    <message>
        <source>axial depth: %1 mm is not within the ball, 0 to %2 mm at lead %3° and tilt %4° (001 models the ball only)</source>
        <translation>Axiale Zustellung: %1 mm liegt nicht innerhalb der Kugel, 0 bis %2 mm bei Anstellwinkel %3° und Kippwinkel %4° (001 modelliert nur die Kugel)</translation>
    </message>
    <message>
        <source>the tip of the ball, where the cutting speed is zero, is in the cut (lead %1°, tilt %2°): the force model takes no account of the rubbing there</source>
        <translation>die Spitze der Kugel, wo die Schnittgeschwindigkeit null ist, ist im Schnitt (Anstellwinkel %1°, Kippwinkel %2°): das Kraftmodell berücksichtigt das Reiben dort nicht</translation>
    </message>
    <message>
        <source>the lead is negative (%1°): the feed has a part along the tool axis and the cut drills, where 001 §5 finds its force model below the measured forces</source>
        <translation>der Anstellwinkel ist negativ (%1°): der Vorschub hat einen Anteil entlang der Werkzeugachse und der Schnitt bohrt, wo 001 §5 sein Kraftmodell unter den gemessenen Kräften findet</translation>
    </message>
    <message>
        <source>the lateral force peaks at %1 N, beyond the 1000 N for which 001 calibrated the holder springs it gives (001 §4): the deflection there is an extrapolation; give your holder&apos;s springs</source>
        <translation>die Querkraft erreicht %1 N, mehr als die 1000 N, für die 001 die angegebenen Federn der Aufnahme kalibriert hat (001 §4): die Verformung dort ist extrapoliert; geben Sie die Federn Ihrer Aufnahme an</translation>
    </message>
</context>
<context>
    <name>CadImportJson</name>
    <message>
        <source>the import&apos;s result has no valid &quot;%1&quot;</source>
        <translation>das Ergebnis des Imports hat kein gültiges „%1“</translation>
    </message>
    <message>
        <source>%1: expected an array, found %2</source>
        <translation>%1: Liste erwartet, gefunden: %2</translation>
    </message>
    <message>
        <source>%1: expected an object, found %2</source>
        <translation>%1: Objekt erwartet, gefunden: %2</translation>
    </message>
    <message>
        <source>the import&apos;s result has no valid &quot;milled_features&quot;: %1</source>
        <translation>das Ergebnis des Imports hat kein gültiges „milled_features“: %1</translation>
    </message>
</context>
<context>
    <name>CalculixText</name>
    <message>
        <source>CalculiX wrote displacements for %1 of the %2 load cases</source>
        <translation>CalculiX hat Verschiebungen für %1 der %2 Lastfälle geschrieben</translation>
    </message>
</context>
<context>
    <name>ClampingAdvice</name>
    <message>
        <source>meets every constraint: %1 %2 per part</source>
        <translation>erfüllt alle Randbedingungen: %1 %2 je Teil</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>cost</source>
        <translation>Kosten</translation>
    </message>
    <message>
        <source>no plan meets every constraint: %1</source>
        <translation>kein Plan erfüllt alle Randbedingungen: %1</translation>
    </message>
    <message>
        <source>no cylinder at the left end of the part for the chuck jaws to grip</source>
        <translation>kein Zylinder am linken Ende des Teils, an dem die Spannbacken greifen können</translation>
    </message>
    <message>
        <source>cannot be planned</source>
        <translation>nicht planbar</translation>
    </message>
    <message>
        <source>; deciding: %1, %2 of %3 %4 (%5 % used)</source>
        <translation>; entscheidend: %1, %2 von %3 %4 (%5 % genutzt)</translation>
    </message>
    <message>
        <source>no cylinder at the right end of the part for the chuck jaws to grip</source>
        <translation>kein Zylinder am rechten Ende des Teils, an dem die Spannbacken greifen können</translation>
    </message>
    <message>
        <source>; the right end face is held by a centre: it is faced and centred before the set-up, not in this time</source>
        <translation>; die rechte Stirnfläche hält eine Spitze: sie wird vor dem Aufspannen plangedreht und zentriert, nicht in dieser Zeit</translation>
    </message>
    <message>
        <source>; not held to: %1</source>
        <translation>; nicht berücksichtigt: %1</translation>
    </message>
    <message>
        <source>meets every constraint it can check, but not every tolerance is one: %1 %2 per part</source>
        <translation>erfüllt alle prüfbaren Randbedingungen, aber nicht jede Toleranz ist eine: %1 %2 je Teil</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]

TolTurn&apos;s command-line front end: the same computations as the desktop program, headless, for batch use and regression tests.

Commands:
</source>
        <translation>Aufruf: %1 [--help] [--version] BEFEHL [ARGUMENTE]

Die Kommandozeilenoberfläche von TolTurn: dieselben Berechnungen wie das Desktop-Programm, ohne grafische Oberfläche, für Stapelverarbeitung und Regressionstests.

Befehle:
</translation>
    </message>
    <message>
        <source>
Run &apos;%1 COMMAND --help&apos; for the options of a command.
Exit codes: 0 success, 1 the input has errors, 2 wrong command line.
</source>
        <translation>
&apos;%1 BEFEHL --help&apos; zeigt die Optionen eines Befehls.
Exit-Codes: 0 Erfolg, 1 die Eingabe enthält Fehler, 2 fehlerhafte Kommandozeile.
</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Diese Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>Usage: %1 %2</source>
        <translation>Aufruf: %1 %2</translation>
    </message>
    <message>
        <source>give exactly one project file</source>
        <translation>geben Sie genau eine Projektdatei an</translation>
    </message>
    <message>
        <source>Print the findings as JSON on standard output.</source>
        <translation>Befunde als JSON auf der Standardausgabe ausgeben.</translation>
    </message>
    <message>
        <source>Project files to check.</source>
        <translation>Zu prüfende Projektdateien.</translation>
    </message>
    <message>
        <source>no project file given</source>
        <translation>keine Projektdatei angegeben</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>Forces (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial</source>
        <translation>Kräfte (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial</translation>
    </message>
    <message>
        <source>Pass %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max %8 kW, %9 N·m</source>
        <translation>Schnitt %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max. %8 kW, %9 N·m</translation>
    </message>
    <message>
        <source>note: </source>
        <translation>Hinweis: </translation>
    </message>
    <message>
        <source>feature  side   z from–to [mm]    radial deviation [µm] min … max   diameter error [µm] min … max</source>
        <translation>Element  Seite  z von–bis [mm]    Radialabweichung [µm] min … max   Durchmesserfehler [µm] min … max</translation>
    </message>
    <message>
        <source>face %1 at z = %2 mm: tan(theta) = %3, axial run-out e = %4 µm</source>
        <translation>Planfläche %1 bei z = %2 mm: tan(theta) = %3, Planlauf e = %4 µm</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Use these forces [N] instead of the force model: radial, tangential, axial.</source>
        <translation>Diese Kräfte [N] statt des Kraftmodells verwenden: radial, tangential, axial.</translation>
    </message>
    <message>
        <source>Rigid machine supports, no toolpost or thermal term: the beam alone.</source>
        <translation>Starre Maschinenabstützungen, ohne Werkzeugträger- und Wärmeanteil: nur der Balken.</translation>
    </message>
    <message>
        <source>Tool positions per turned feature (default 21).</source>
        <translation>Werkzeugpositionen je gedrehtem Formelement (Standard 21).</translation>
    </message>
    <message>
        <source>Ignore the stock still on the uncut side of the tool.</source>
        <translation>Das noch auf der ungeschnittenen Seite des Werkzeugs stehende Material ignorieren.</translation>
    </message>
    <message>
        <source>Project file.</source>
        <translation>Projektdatei.</translation>
    </message>
    <message>
        <source>--stations must be a whole number from 2 to 100000, not &quot;%1&quot;</source>
        <translation>--stations muss eine ganze Zahl von 2 bis 100000 sein, nicht „%1“</translation>
    </message>
    <message>
        <source>K_n = %1 N/mm², K_f = %2 (Li &amp; Du eq. 15), RMS residual %3 N over %4 cuts</source>
        <translation>K_n = %1 N/mm², K_f = %2 (Li &amp; Du Gl. 15), RMS-Restfehler %3 N über %4 Schnitte</translation>
    </message>
    <message>
        <source>   f [mm/rev]  d [mm]   Ft meas   Ft model   Fa meas   Fa model   Fr model [N]</source>
        <translation>   f [mm/rev]  d [mm]   Ft gem.  Ft Modell   Fa gem.  Fa Modell  Fr Modell [N]</translation>
    </message>
    <message>
        <source>Store K_n and K_f in the project (force model li_du) and save it.</source>
        <translation>K_n und K_f im Projekt hinterlegen (Kraftmodell li_du) und das Projekt speichern.</translation>
    </message>
    <message>
        <source>Project file (its tool gives the geometry).</source>
        <translation>Projektdatei (ihr Werkzeug liefert die Geometrie).</translation>
    </message>
    <message>
        <source>CSV of measured cuts: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N.</source>
        <translation>CSV der gemessenen Schnitte: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N.</translation>
    </message>
    <message>
        <source>give a project file and a measurements file</source>
        <translation>geben Sie eine Projektdatei und eine Messdatei an</translation>
    </message>
    <message>
        <source>wrote %1: force model li_du</source>
        <translation>%1 geschrieben: Kraftmodell li_du</translation>
    </message>
    <message>
        <source>the nominal size must be a number in mm, not &quot;%1&quot;</source>
        <translation>das Nennmaß muss eine Zahl in mm sein, nicht „%1“</translation>
    </message>
    <message>
        <source>Print the limits as JSON.</source>
        <translation>Grenzabmaße als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Nominal size [mm].</source>
        <translation>Nennmaß [mm].</translation>
    </message>
    <message>
        <source>Tolerance class, e.g. H7, g6, js12.</source>
        <translation>Toleranzklasse, z. B. H7, g6, js12.</translation>
    </message>
    <message>
        <source>give a nominal size and a tolerance class, e.g. 50 H7</source>
        <translation>geben Sie ein Nennmaß und eine Toleranzklasse an, z. B. 50 H7</translation>
    </message>
    <message>
        <source>%1 %2: upper %3 µm, lower %4 µm (%5 = %6 µm)</source>
        <translation>%1 %2: oberes Grenzabmaß %3 µm, unteres Grenzabmaß %4 µm (%5 = %6 µm)</translation>
    </message>
    <message>
        <source>Print the fit as JSON.</source>
        <translation>Passung als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Hole and shaft class, e.g. H7/g6.</source>
        <translation>Toleranzklasse von Bohrung und Welle, z. B. H7/g6.</translation>
    </message>
    <message>
        <source>give a nominal size and a fit, e.g. 50 H7/g6</source>
        <translation>geben Sie ein Nennmaß und eine Passung an, z. B. 50 H7/g6</translation>
    </message>
    <message>
        <source>%1 %2/%3: %4 fit; hole %5/%6 µm, shaft %7/%8 µm; clearance max %9 µm, min %10 µm (negative: interference)</source>
        <translation>%1 %2/%3: %4; Bohrung %5/%6 µm, Welle %7/%8 µm; Spiel max. %9 µm, min. %10 µm (negativ: Übermaß)</translation>
    </message>
    <message>
        <source>Print the verdicts as JSON.</source>
        <translation>Bewertungen als JSON ausgeben.</translation>
    </message>
    <message>
        <source>tolerance  type                    feature  value [µm]  limit [µm]  use [%]  verdict</source>
        <translation>Toleranz   Typ                     Element   Wert [µm] Grenze [µm] Ausn. [%] Bewertung</translation>
    </message>
    <message>
        <source>Optimum (%1)</source>
        <translation>Optimum (%1)</translation>
    </message>
    <message>
        <source>No plan meets every constraint; the one that violates them least</source>
        <translation>Kein Plan erfüllt alle Randbedingungen; der Plan mit der geringsten Verletzung</translation>
    </message>
    <message>
        <source>  finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>  Schlichten: vc %1 m/min, f %2 mm/rev, ap %3 mm</translation>
    </message>
    <message>
        <source>  binding: </source>
        <translation>  begrenzend: </translation>
    </message>
    <message>
        <source>  violated: </source>
        <translation>  verletzt: </translation>
    </message>
    <message>
        <source>Print the plan as JSON.</source>
        <translation>Plan als JSON ausgeben.</translation>
    </message>
    <message>
        <source>time or cost (default: the project&apos;s).</source>
        <translation>time oder cost (Standard: die Vorgabe des Projekts).</translation>
    </message>
    <message>
        <source>Store the optimal passes in the project (replacing its passes) and save it.</source>
        <translation>Die optimalen Schnitte im Projekt hinterlegen (ersetzt dessen Schnitte) und das Projekt speichern.</translation>
    </message>
    <message>
        <source>--objective is time or cost, not &quot;%1&quot;</source>
        <translation>--objective ist time oder cost, nicht „%1“</translation>
    </message>
    <message>
        <source>feed-speed (default) or feed-depth.</source>
        <translation>feed-speed (Standard) oder feed-depth.</translation>
    </message>
    <message>
        <source>Print every grid point as CSV.</source>
        <translation>Jeden Rasterpunkt als CSV ausgeben.</translation>
    </message>
    <message>
        <source>Points along each axis (default 256).</source>
        <translation>Punkte je Achse (Standard 256).</translation>
    </message>
    <message>
        <source>give one project file, --plane feed-speed or feed-depth, --size from 2 to 4096</source>
        <translation>geben Sie eine Projektdatei an, --plane feed-speed oder feed-depth, --size von 2 bis 4096</translation>
    </message>
    <message>
        <source>  bounded by %1 (%2 points beyond it)</source>
        <translation>  begrenzt durch %1 (%2 Punkte jenseits davon)</translation>
    </message>
    <message>
        <source>Print the ranking as JSON.</source>
        <translation>Rangfolge als JSON ausgeben.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE.pdf</source>
        <translation>geben Sie eine Projektdatei und -o DATEI.pdf an</translation>
    </message>
    <message>
        <source>%1: %2 pages</source>
        <translation>%1: %2 Seiten</translation>
    </message>
    <message>
        <source>Validate project files: report every problem with the field and value; exit 1 on errors.</source>
        <translation>Projektdateien prüfen: jedes Problem mit Feld und Wert melden; bei Fehlern Exit-Code 1.</translation>
    </message>
    <message>
        <source>Predict the deviation at each tool position along every turned feature: radial and tangential, total and per contribution (spindle–chuck, toolpost, workpiece, thermal), with the forces used.</source>
        <translation>Die Abweichung an jeder Werkzeugposition entlang jedes gedrehten Formelements vorhersagen: radial und tangential, gesamt und je Anteil (Spindel–Futter, Werkzeugträger, Werkstück, thermisch), mit den verwendeten Kräften.</translation>
    </message>
    <message>
        <source>Fit the Li &amp; Du coefficients K_n and K_f to measured tangential and axial forces (eq. 17–18) for the project&apos;s tool; --write stores them in the project.</source>
        <translation>Die Koeffizienten K_n und K_f nach Li &amp; Du für das Werkzeug des Projekts an gemessene Tangential- und Axialkräfte anpassen (Gl. 17–18); --write speichert sie im Projekt.</translation>
    </message>
    <message>
        <source>ISO 286 limits of a tolerance class at a nominal size, e.g. &apos;iso286 50 H7&apos;.</source>
        <translation>Grenzabmaße einer Toleranzklasse nach ISO 286 bei einem Nennmaß, z. B. &apos;iso286 50 H7&apos;.</translation>
    </message>
    <message>
        <source>ISO 286 fit of a hole and a shaft class, e.g. &apos;fit 50 H7/g6&apos;: type and clearances.</source>
        <translation>Passung nach ISO 286 aus Bohrungs- und Wellenklasse, z. B. &apos;fit 50 H7/g6&apos;: Art und Spiele.</translation>
    </message>
    <message>
        <source>Every tolerance of the project against the predicted deviation: value, limit, utilisation, the deciding condition of Valiño et al. Fig. 4, and the verdict.</source>
        <translation>Jede Toleranz des Projekts gegenüber der vorhergesagten Abweichung: Wert, Grenze, Ausnutzung, die entscheidende Bedingung nach Valiño et al., Abb. 4, und die Bewertung.</translation>
    </message>
    <message>
        <source>Cutting conditions of the finishing and roughing passes at least time or cost per part under every constraint (tolerances, roughness, power, torque, force, spindle speed, tool life).</source>
        <translation>Schnittbedingungen der Schlicht- und Schruppschnitte mit minimaler Zeit oder minimalen Kosten je Teil unter allen Randbedingungen (Toleranzen, Rauheit, Leistung, Drehmoment, Kraft, Drehzahl, Standzeit).</translation>
    </message>
    <message>
        <source>The cutting window of the finishing pass around the optimum: per grid point the objective, whether it is feasible and the constraint that bounds it.</source>
        <translation>Das Schnittwertfenster des Schlichtschnitts um das Optimum: je Rasterpunkt die Zielfunktion, ob er zulässig ist, und die Randbedingung, die ihn begrenzt.</translation>
    </message>
    <message>
        <source>The optimal plan for chuck, between centres and chuck + tailstock, ranked, with the reason.</source>
        <translation>Der optimale Plan für Futter, zwischen Spitzen sowie Futter + Reitstock, nach Rang geordnet, mit Begründung.</translation>
    </message>
    <message>
        <source>The PDF report: part, inputs, predicted deviation, tolerance verdicts, plan with the cutting window, clamping ranking, compensation, assumptions and sources.</source>
        <translation>Der PDF-Bericht: Teil, Eingaben, vorhergesagte Abweichung, Toleranzbewertungen, Plan mit Schnittwertfenster, Rangfolge der Aufspannungen, Kompensation, Annahmen und Quellen.</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Maschine: %1</translation>
    </message>
    <message>
        <source>at the compliant end: %1</source>
        <translation>am nachgiebigen Ende: %1</translation>
    </message>
    <message>
        <source>chuck stiffness needed: %1</source>
        <translation>nötige Futtersteifigkeit: %1</translation>
    </message>
    <message>
        <source>tailstock stiffness needed: %1</source>
        <translation>nötige Reitstocksteifigkeit: %1</translation>
    </message>
    <message>
        <source>Plan for the compliant (default) or the stiff end of an unmeasured machine&apos;s stiffness range.</source>
        <translation>Für das nachgiebige (Vorgabe) oder das steife Ende des Steifigkeitsbereichs einer nicht gemessenen Maschine planen.</translation>
    </message>
    <message>
        <source>--machine-end is compliant or stiff, not &quot;%1&quot;</source>
        <translation>--machine-end ist compliant oder stiff, nicht „%1“</translation>
    </message>
    <message>
        <source>%1: unknown command &apos;%2&apos;.</source>
        <translation>%1: unbekannter Befehl &apos;%2&apos;.</translation>
    </message>
    <message>
        <source>Did you mean &apos;%1&apos;?</source>
        <translation>Meinten Sie &apos;%1&apos;?</translation>
    </message>
    <message>
        <source>Run &apos;%1 --help&apos; for the list of commands.</source>
        <translation>&apos;%1 --help&apos; listet die Befehle.</translation>
    </message>
    <message>
        <source>The planner&apos;s name for the title block.</source>
        <translation>Der Name des Planers für das Schriftfeld.</translation>
    </message>
    <message>
        <source>cannot write to standard output: %1</source>
        <translation>Standardausgabe kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>PDF file to write (&apos;-&apos;: standard output).</source>
        <translation>Zu schreibende PDF-Datei (&apos;-&apos;: Standardausgabe).</translation>
    </message>
    <message>
        <source>part &quot;%1&quot;, %2 mm long, %3 outer and %4 inner features, %5, %6, %7</source>
        <translation>Teil „%1“, %2 mm lang, %3 äußere und %4 innere Formelemente, %5, %6, %7</translation>
    </message>
    <message numerus="yes">
        <source>%n pass(es)</source>
        <translation>
            <numerusform>%n Schnitt</numerusform>
            <numerusform>%n Schnitte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n tolerance(s)</source>
        <translation>
            <numerusform>%n Toleranz</numerusform>
            <numerusform>%n Toleranzen</numerusform>
        </translation>
    </message>
    <message>
        <source>the result is not finite at &apos;%1&apos;: the inputs lie beyond what the model computes (see the input bounds in docs/project-format.md)</source>
        <translation>das Ergebnis ist bei &apos;%1&apos; nicht endlich: Die Eingaben liegen jenseits dessen, was das Modell berechnet (siehe die Eingabegrenzen in docs/project-format.md)</translation>
    </message>
    <message>
        <source>--load takes three numbers in newtons, radial,tangential,axial (e.g. 200,500,150), each at most 1e6, not &quot;%1&quot;</source>
        <translation>--load nimmt drei Zahlen in Newton, radial,tangential,axial (z. B. 200,500,150), jede höchstens 1e6, nicht &quot;%1&quot;</translation>
    </message>
    <message>
        <source>--stations %1 on %2 features makes %3 tool positions, more than the %4 computed at once; give at most %5</source>
        <translation>--stations %1 auf %2 Formelementen ergibt %3 Werkzeugstellungen, mehr als die %4, die auf einmal berechnet werden; geben Sie höchstens %5 an</translation>
    </message>
    <message>
        <source>Best plan (%1) found within the time limit</source>
        <translation>Bester Plan (%1) innerhalb der Zeitgrenze</translation>
    </message>
    <message>
        <source>Stop the search after SECONDS (0.01 to 3600, default 60) with the best plan found by then.</source>
        <translation>Die Suche nach SECONDS (0,01 bis 3600, Vorgabe 60) mit dem bis dahin besten Plan beenden.</translation>
    </message>
    <message>
        <source>--time-limit is from 0.01 to 3600 seconds, not &quot;%1&quot;</source>
        <translation>--time-limit liegt zwischen 0,01 und 3600 Sekunden, nicht „%1“</translation>
    </message>
    <message>
        <source>Learn what a machine&apos;s measured parts show beyond the physics (Li &amp; Du): geometric error, hybrid RBF network, and how well parts not learned from are predicted with and without it.</source>
        <translation>Lernen, was die gemessenen Teile einer Maschine über die Physik hinaus zeigen (Li &amp; Du): geometrischer Fehler, hybrides RBF-Netz und wie gut nicht gelernte Teile mit und ohne es vorhergesagt werden.</translation>
    </message>
    <message>
        <source>With what was learned of %1 (model %2, %3 parts; parts left out predicted to %4 µm RMS, the physics alone %5 µm):</source>
        <translation>Mit dem, was von %1 gelernt wurde (Modell %2, %3 Teile; weggelassene Teile auf %4 µm RMS vorhergesagt, die Physik allein %5 µm):</translation>
    </message>
    <message>
        <source>radius error %1 … %2 µm</source>
        <translation>Radiusfehler %1 … %2 µm</translation>
    </message>
    <message>
        <source>Add what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Hinzufügen, was von der Maschine aus ihren gemessenen Teilen gelernt wurde (learn --save).</translation>
    </message>
    <message>
        <source>The measurement store: an SQLite file, or postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).</source>
        <translation>Der Messwertspeicher: eine SQLite-Datei oder postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (Vorgabe: %1).</translation>
    </message>
    <message>
        <source>Machine: learned from measured parts (%1); parts left out were predicted to %2 µm RMS, the physics alone to %3 µm</source>
        <translation>Maschine: aus gemessenen Teilen gelernt (%1); weggelassene Teile auf %2 µm RMS vorhergesagt, die Physik allein auf %3 µm</translation>
    </message>
    <message>
        <source>Judge with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Mit dem urteilen, was von der Maschine aus ihren gemessenen Teilen gelernt wurde (learn --save).</translation>
    </message>
    <message>
        <source>Plan with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Mit dem planen, was von der Maschine aus ihren gemessenen Teilen gelernt wurde (learn --save).</translation>
    </message>
    <message>
        <source>--learned replaces the stiffness range: give it or --machine-end, not both</source>
        <translation>--learned ersetzt den Steifigkeitsbereich: geben Sie es oder --machine-end an, nicht beides</translation>
    </message>
    <message>
        <source>Base the report on what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Den Bericht auf das stützen, was aus den gemessenen Teilen über die Maschine gelernt wurde (learn --save).</translation>
    </message>
    <message>
        <source>The operation (set-up) to work on, by its name (default: the first).</source>
        <translation>Die Aufspannung (Operation), mit der gearbeitet wird, über ihren Namen (Standard: die erste).</translation>
    </message>
    <message>
        <source>--operation: the project has no operation &quot;%1&quot;; it has: %2</source>
        <translation>--operation: das Projekt hat keine Aufspannung &quot;%1&quot;; vorhanden sind: %2</translation>
    </message>
    <message>
        <source>the project has %1 operations (%2); this is %3 (--operation NAME for another)</source>
        <translation>das Projekt hat %1 Aufspannungen (%2); dies ist %3 (--operation NAME für eine andere)</translation>
    </message>
    <message>
        <source>%1 (operation %2 of %3): %4, the %5 end held</source>
        <translation>%1 (Aufspannung %2 von %3): %4, Ende %5 gespannt</translation>
    </message>
    <message>
        <source>%1 (%2, %3 end held)</source>
        <translation>%1 (%2, Ende %3 gespannt)</translation>
    </message>
    <message numerus="yes">
        <source>; %n set-up(s): </source>
        <translation>
            <numerusform>; %n Aufspannung: </numerusform>
            <numerusform>; %n Aufspannungen: </numerusform>
        </translation>
    </message>
    <message>
        <source>Split into operations: %1 (Edit &gt; Operations…, or further_operations in the file)</source>
        <translation>In Aufspannungen aufteilen: %1 (Bearbeiten &gt; Aufspannungen… oder further_operations in der Datei)</translation>
    </message>
    <message>
        <source>collet stiffness needed: %1</source>
        <translation>nötige Steifigkeit der Spannzange: %1</translation>
    </message>
    <message>
        <source>Plain Timoshenko beam: without the corrections for the root in the jaws and the shoulders identified from solid FE.</source>
        <translation>Reiner Timoshenko-Balken: ohne die aus Volumen-FE ermittelten Korrekturen für die Einspannung in den Backen und die Absätze.</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a number from %3 to %4</source>
        <translation>--%1: „%2“ ist keine Zahl von %3 bis %4</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a whole number from %3 to %4</source>
        <translation>--%1: „%2“ ist keine ganze Zahl von %3 bis %4</translation>
    </message>
    <message numerus="yes">
        <source>, %n milled feature(s)</source>
        <translation>
            <numerusform>, %n gefrästes Formelement</numerusform>
            <numerusform>, %n gefräste Formelemente</numerusform>
        </translation>
    </message>
    <message>
        <source>Number of the pass, 1 for the first (default: the last finishing pass).</source>
        <translation>Nummer des Schnitts, 1 für den ersten (Standard: der letzte Schlichtschnitt).</translation>
    </message>
    <message>
        <source>--pass must be a pass number (1, 2, …), not &quot;%1&quot;</source>
        <translation>--pass muss eine Schnittnummer sein (1, 2, …), nicht „%1“</translation>
    </message>
    <message>
        <source>warning: %1: dropped with the passes it was on</source>
        <translation>Warnung: %1: mit den Schnitten entfernt, an denen es stand</translation>
    </message>
    <message>
        <source>the output &apos;%1&apos; is the input file &apos;%2&apos;: give another output file, so that the input is not overwritten</source>
        <translation>die Ausgabe &apos;%1&apos; ist die Eingabedatei &apos;%2&apos;: geben Sie eine andere Ausgabedatei an, damit die Eingabe nicht überschrieben wird</translation>
    </message>
    <message>
        <source>there is no measurement store %1: &apos;measurements add&apos; stores the first part in it</source>
        <translation>es gibt keinen Messwertspeicher %1: &apos;measurements add&apos; legt das erste Teil darin ab</translation>
    </message>
    <message>
        <source>the output &apos;%1&apos; is the measurement store &apos;%2&apos;: give another output file, so that the store is not overwritten</source>
        <translation>die Ausgabe &apos;%1&apos; ist der Messwertspeicher &apos;%2&apos;: geben Sie eine andere Ausgabedatei an, damit der Speicher nicht überschrieben wird</translation>
    </message>
    <message>
        <source>%1 × %2 window, %3 % feasible; %4</source>
        <translation>Fenster %1 × %2, %3 % zulässig; %4</translation>
    </message>
    <message>
        <source>%1%2: the value is empty; give one, or leave the option out for its default</source>
        <translation>%1%2: der Wert ist leer; geben Sie einen an, oder lassen Sie die Option für ihren Standardwert weg</translation>
    </message>
    <message>
        <source>  to meet it: </source>
        <translation>  um sie einzuhalten: </translation>
    </message>
    <message numerus="yes">
        <source>  roughing: %n pass(es) of ap %1 mm at vc %2 m/min, f %3 mm/rev</source>
        <translation>
            <numerusform>  Schruppen: %n Schnitt mit ap %1 mm bei vc %2 m/min, f %3 mm/rev</numerusform>
            <numerusform>  Schruppen: %n Schnitte mit ap %1 mm bei vc %2 m/min, f %3 mm/rev</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>wrote %1: %n pass(es)</source>
        <translation>
            <numerusform>%1 geschrieben: %n Schnitt</numerusform>
            <numerusform>%1 geschrieben: %n Schnitte</numerusform>
        </translation>
    </message>
    <message>
        <source>Boring bar %1 (%2): Fc = %3 N, Ff = %4 N, Fp = %5 N; tip compliance %6 µm/N; Ra %7 µm, Rz %8 µm</source>
        <translation>Bohrstange %1 (%2): Fc = %3 N, Ff = %4 N, Fp = %5 N; Nachgiebigkeit an der Spitze %6 µm/N; Ra %7 µm, Rz %8 µm</translation>
    </message>
    <message>
        <source>  time per part %1 min (finishing %2, roughing %3, handling %4, tool changes %5), cost %6 at %7 per min, %8</source>
        <translation>  Zeit je Teil %1 min (Schlichten %2, Schruppen %3, Handhabung %4, Werkzeugwechsel %5), Kosten %6 bei %7 je min, %8</translation>
    </message>
    <message>
        <source>%1 tool edges per part</source>
        <translation>%1 Schneiden je Teil</translation>
    </message>
    <message>
        <source>tool edges per part not known (no tool life)</source>
        <translation>Schneiden je Teil nicht bekannt (keine Standzeit)</translation>
    </message>
    <message>
        <source>vc = %1 m/min</source>
        <translation>vc = %1 m/min</translation>
    </message>
    <message>
        <source>ap = %1 mm</source>
        <translation>ap = %1 mm</translation>
    </message>
    <message>
        <source>optimum at f = %1 mm/rev, %2</source>
        <translation>Optimum bei f = %1 mm/rev, %2</translation>
    </message>
    <message>
        <source>no plan meets every constraint; the one that violates them least at f = %1 mm/rev, %2</source>
        <translation>kein Plan erfüllt alle Randbedingungen; der Plan mit der geringsten Verletzung bei f = %1 mm/rev, %2</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>nicht bekannt</translation>
    </message>
</context>
<context>
    <name>Compensation</name>
    <message>
        <source>the face&apos;s conicity needs a correction along Z, which TolTurn does not generate: reduce the feed or change the clamping</source>
        <translation>die Konizität der Planfläche erfordert eine Korrektur entlang Z, die TolTurn nicht erzeugt: verringern Sie den Vorschub oder ändern Sie die Aufspannung</translation>
    </message>
    <message>
        <source>%1: the correction, %2 µm, is larger than the finishing depth of cut %3 mm: the prediction, made for that depth, does not hold there and the correction is not a program to run; support the part (tailstock, steady rest), cut less or check the machine&apos;s data</source>
        <translation>%1: die Korrektur, %2 µm, ist größer als die Schlichtschnitttiefe %3 mm: die Vorhersage, für diese Tiefe gemacht, gilt dort nicht, und die Korrektur ist kein Programm, das man laufen lassen kann; stützen Sie das Teil (Reitstock, Lünette), schneiden Sie weniger tief oder prüfen Sie die Maschinendaten</translation>
    </message>
</context>
<context>
    <name>ControlCommand</name>
    <message>
        <source>roughing</source>
        <translation>Schruppen</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>Schlichten</translation>
    </message>
    <message>
        <source>%1: constant-force control, adaptive against the programmed feed</source>
        <translation>%1: Konstantkraftregelung, adaptiv gegen den programmierten Vorschub</translation>
    </message>
    <message>
        <source>Pass %1 (%2): f %3 mm/rev, a_p %4 mm, vc %5 m/min; set force %6 N (F ∝ f^%7)</source>
        <translation>Schnitt %1 (%2): f %3 mm/U, a_p %4 mm, vc %5 m/min; Sollkraft %6 N (F ∝ f^%7)</translation>
    </message>
    <message>
        <source>constant feed</source>
        <translation>konstanter Vorschub</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptiv</translation>
    </message>
    <message>
        <source>time in cut [s]</source>
        <translation>Zeit im Schnitt [s]</translation>
    </message>
    <message>
        <source>%1 (%2 %)</source>
        <translation>%1 (%2 %)</translation>
    </message>
    <message>
        <source>peak force [N]</source>
        <translation>Spitzenkraft [N]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>Vorschub [mm/U]</translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation>Abweichung [µm]</translation>
    </message>
    <message>
        <source>largest Ra [µm]</source>
        <translation>größtes Ra [µm]</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>Constant-force adaptive control of the plan&apos;s passes (Čuš &amp; Župerl): the feed override commanded every 20 ms through the feed drive&apos;s dynamics, against the programmed feed: time, peak force, feed, deviation and roughness along the pass.</source>
        <translation>Adaptive Konstantkraftregelung der Schnitte des Plans (Čuš &amp; Župerl): der Vorschub-Override alle 20 ms über die Dynamik des Vorschubantriebs vorgegeben, gegen den programmierten Vorschub: Zeit, Spitzenkraft, Vorschub, Abweichung und Rauheit entlang des Schnitts.</translation>
    </message>
    <message>
        <source>Print a summary per pass as JSON.</source>
        <translation>Eine Zusammenfassung je Schnitt als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Print every control period of both runs as CSV.</source>
        <translation>Jeden Regeltakt beider Läufe als CSV ausgeben.</translation>
    </message>
    <message>
        <source>Only pass N of the plan (1, 2, …).</source>
        <translation>Nur Schnitt N des Plans (1, 2, …).</translation>
    </message>
    <message>
        <source>The resultant force to hold in N (default: the programmed feed&apos;s at the pass&apos;s depth).</source>
        <translation>Die zu haltende resultierende Kraft in N (Vorgabe: die des programmierten Vorschubs bei der Schnitttiefe des Schnitts).</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force in % (default 0).</source>
        <translation>Maschinenrauschen: Standardabweichung der gemessenen Kraft in % (Vorgabe 0).</translation>
    </message>
    <message>
        <source>Seed of the noise (default 1).</source>
        <translation>Startwert des Rauschens (Vorgabe 1).</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>Die Projektdatei.</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>--json oder --csv angeben, nicht beides</translation>
    </message>
    <message>
        <source>Weight of each period&apos;s estimate of the process gain, %1–%2 (default 1; tune-control finds it).</source>
        <translation>Gewicht der Schätzung der Prozessverstärkung je Takt, %1–%2 (Vorgabe 1; tune-control ermittelt es).</translation>
    </message>
    <message>
        <source>Share of the step to the set force&apos;s feed commanded each period, %1–%2 (default 1).</source>
        <translation>Anteil des Schritts zum Vorschub der Sollkraft, der je Takt vorgegeben wird, %1–%2 (Vorgabe 1).</translation>
    </message>
    <message>
        <source>%1: controller tuning on pass %2, RMS of F / F_set − 1 over the cut</source>
        <translation>%1: Reglerabstimmung an Schnitt %2, Effektivwert von F / F_soll − 1 über den Schnitt</translation>
    </message>
    <message>
        <source>untuned (both gains 1): %1 %</source>
        <translation>nicht abgestimmt (beide Verstärkungen 1): %1 %</translation>
    </message>
    <message>
        <source>method</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>estimator</source>
        <translation>Schätzer</translation>
    </message>
    <message>
        <source>command</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <source>RMS [%]</source>
        <translation>Effektivwert [%]</translation>
    </message>
    <message>
        <source>evaluations</source>
        <translation>Auswertungen</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>--methods: &quot;%1&quot; is not a method (%2)</source>
        <translation>--methods: „%1“ ist kein Verfahren (%2)</translation>
    </message>
    <message>
        <source>Tune the constant-force controller on a pass of the plan (the estimator&apos;s and the command&apos;s gains): particle swarm (Čuš &amp; Župerl&apos;s method, pagmo2) against NLopt&apos;s algorithms on the same objective.</source>
        <translation>Den Konstantkraftregler an einem Schnitt des Plans abstimmen (Verstärkung des Schätzers und der Vorgabe): Partikelschwarm (das Verfahren von Čuš &amp; Župerl, pagmo2) gegen die Algorithmen von NLopt auf derselben Zielfunktion.</translation>
    </message>
    <message>
        <source>Print the comparison as JSON.</source>
        <translation>Den Vergleich als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Comma-separated methods (default all: %1).</source>
        <translation>Verfahren, durch Kommas getrennt (Vorgabe alle: %1).</translation>
    </message>
    <message>
        <source>--methods: no method named</source>
        <translation>--methods: kein Verfahren genannt</translation>
    </message>
    <message>
        <source>Simulations of the pass each method may ask for, at least %1 (default 400).</source>
        <translation>Simulationen des Schnitts, die jedes Verfahren anfordern darf, mindestens %1 (Vorgabe 400).</translation>
    </message>
</context>
<context>
    <name>ControlExample</name>
    <message>
        <source>Čuš &amp; Župerl&apos;s end-milling system rebuilt (docs/adaptive.md §9)</source>
        <translation>Das Stirnfräs-System von Čuš &amp; Župerl nachgebaut (docs/adaptive.md §9)</translation>
    </message>
    <message>
        <source>Cut data: mean forces of the linear edge-force model (Altintas 2012 §2.4), Al7075-T6, carbide, dry: Ktc %1, Krc %2, Kac %3 N/mm², Kte %4, Kre %5, Kae %6 N/mm (CJME 2021, doi:10.1186/s10033-021-00536-9, table 5); 004 gives neither its data nor its material.</source>
        <translation>Schnittdaten: mittlere Kräfte des linearen Schneidkantenkraftmodells (Altintas 2012 §2.4), Al7075-T6, Hartmetall, trocken: Ktc %1, Krc %2, Kac %3 N/mm², Kte %4, Kre %5, Kae %6 N/mm (CJME 2021, doi:10.1186/s10033-021-00536-9, Tabelle 5); 004 nennt weder seine Daten noch seinen Werkstoff.</translation>
    </message>
    <message>
        <source>Tool and cut: Ø%1 mm, %2 flutes, down milling, radial depth %3 mm; axial depth %4 mm, at which the model gives the paper&apos;s 181.1 N at 324.61 mm/min and 2201 1/min.</source>
        <translation>Werkzeug und Schnitt: Ø%1 mm, %2 Schneiden, Gleichlauffräsen, radiale Zustellung %3 mm; axiale Zustellung %4 mm, bei der das Modell die 181,1 N des Artikels bei 324,61 mm/min und 2201 1/min ergibt.</translation>
    </message>
    <message>
        <source>Network 8–15–3, ArcTangent, max–min normalised, back-propagation (learning rate 0.05, momentum 0.008, 2000 epochs) on 441 cut points: %1 % RMS error on the 400 between them.</source>
        <translation>Netz 8–15–3, ArcTangens, Max-Min-normiert, Backpropagation (Lernrate 0,05, Momentum 0,008, 2000 Epochen) an 441 Schnittpunkten: %1 % Effektivfehler an den 400 dazwischen.</translation>
    </message>
    <message>
        <source>Off-line PSO-NN: the largest feed rate within %1 N by the network (%2–%3 mm/min, %4–%5 1/min)</source>
        <translation>Offline-PSO-NN: die größte Vorschubgeschwindigkeit innerhalb %1 N nach dem Netz (%2–%3 mm/min, %4–%5 1/min)</translation>
    </message>
    <message numerus="yes">
        <source>%n evaluation(s) of the network</source>
        <translation>
            <numerusform>%n Auswertung des Netzes</numerusform>
            <numerusform>%n Auswertungen des Netzes</numerusform>
        </translation>
    </message>
    <message>
        <source>The loop, table 1 simulation 5: from %1 mm/min and %2 1/min, set force %3 N, %4 s</source>
        <translation>Der Regelkreis, Tabelle 1 Simulation 5: von %1 mm/min und %2 1/min, Sollkraft %3 N, %4 s</translation>
    </message>
    <message>
        <source>uncontrolled</source>
        <translation>ungeregelt</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptiv</translation>
    </message>
    <message>
        <source>paper</source>
        <translation>Artikel</translation>
    </message>
    <message>
        <source>Table 1, every row from its conditions to its force: settled against the paper</source>
        <translation>Tabelle 1, jede Zeile von ihren Bedingungen zu ihrer Kraft: eingeschwungen gegen den Artikel</translation>
    </message>
    <message>
        <source>  * outside the network&apos;s training range: it extrapolates there</source>
        <translation>  * außerhalb des Trainingsbereichs des Netzes: dort extrapoliert es</translation>
    </message>
    <message>
        <source>note: Ra from the printed M5 (eq. 6), which does not reproduce the paper&apos;s table (docs/adaptive.md §2). The spindle follows eq. 1 too: 004 gives no spindle model.</source>
        <translation>Hinweis: Ra aus dem gedruckten M5 (Gl. 6), das die Tabelle des Artikels nicht wiedergibt (docs/adaptive.md §2). Die Spindel folgt ebenfalls Gl. 1: 004 gibt kein Spindelmodell an.</translation>
    </message>
    <message>
        <source>Čuš &amp; Župerl&apos;s own end-milling system rebuilt: the force network trained on cut data, the off-line PSO-NN optimisation, the loop overriding feed and spindle speed, beside the paper&apos;s table 1.</source>
        <translation>Das eigene Stirnfräs-System von Čuš &amp; Župerl nachgebaut: das an Schnittdaten trainierte Kraftnetz, die Offline-Optimierung PSO-NN, der Regelkreis mit Vorschub- und Drehzahl-Override, neben Tabelle 1 des Artikels.</translation>
    </message>
    <message>
        <source>Print the results as JSON.</source>
        <translation>Die Ergebnisse als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Print every control period of both runs as CSV.</source>
        <translation>Jeden Regeltakt beider Läufe als CSV ausgeben.</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force in % (default 0).</source>
        <translation>Maschinenrauschen: Standardabweichung der gemessenen Kraft in % (Vorgabe 0).</translation>
    </message>
    <message>
        <source>Seed of the noise (default 1).</source>
        <translation>Startwert des Rauschens (Vorgabe 1).</translation>
    </message>
    <message>
        <source>Share of a change of chip load the spindle speed takes, 0–1 (default 0.5).</source>
        <translation>Anteil einer Änderung der Spandicke, den die Drehzahl übernimmt, 0–1 (Vorgabe 0,5).</translation>
    </message>
    <message>
        <source>Simulated time in s, 0.1–60 (default 3).</source>
        <translation>Simulierte Zeit in s, 0,1–60 (Vorgabe 3).</translation>
    </message>
    <message>
        <source>takes no file: &quot;%1&quot;</source>
        <translation>nimmt keine Datei: „%1“</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>--json oder --csv angeben, nicht beide</translation>
    </message>
</context>
<context>
    <name>CurrentForces</name>
    <message>
        <source>%1 = %2 is outside the range %3 to %4 of the calibration cuts: the network extrapolates</source>
        <translation>%1 = %2 liegt außerhalb des Bereichs %3 bis %4 der Kalibrierschnitte: Das Netz extrapoliert</translation>
    </message>
    <message>
        <source>a force, the chip area or an angle is not a finite number</source>
        <translation>eine Kraft, der Spanungsquerschnitt oder ein Winkel ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>the uncut chip area A_c = %1 mm² (eq. 16) is not above zero</source>
        <translation>der Spanungsquerschnitt A_c = %1 mm² (Gl. 16) ist nicht größer als null</translation>
    </message>
    <message>
        <source>eq. 17 and 18 do not determine K_n and K_f for back rake %1°, normal rake %2° and effective lead angle %3° (determinant %4)</source>
        <translation>Gl. 17 und 18 bestimmen K_n und K_f nicht für Rückspanwinkel %1°, Normalspanwinkel %2° und wirksamen Anstellwinkel %3° (Determinante %4)</translation>
    </message>
    <message>
        <source>F_t = %1 N and F_a = %2 N give a normal pressure K_n = %3 N/mm² that is not positive (eq. 17–18): check the forces and the tool angles</source>
        <translation>F_t = %1 N und F_a = %2 N ergeben einen Normaldruck K_n = %3 N/mm², der nicht positiv ist (Gl. 17–18): Prüfen Sie die Kräfte und die Werkzeugwinkel</translation>
    </message>
    <message>
        <source>%1 = %2 is not above zero</source>
        <translation>%1 = %2 ist nicht größer als null</translation>
    </message>
    <message>
        <source>the nose radius %1 mm is negative or not a number</source>
        <translation>der Eckenradius %1 mm ist negativ oder keine Zahl</translation>
    </message>
    <message>
        <source>%1 = %2° is not between %3° and %4°</source>
        <translation>%1 = %2° liegt nicht zwischen %3° und %4°</translation>
    </message>
    <message>
        <source>the current–force model has not been trained</source>
        <translation>das Strom-Kraft-Modell wurde nicht trainiert</translation>
    </message>
    <message>
        <source>the radial force cannot be found from the estimated F_t = %1 N and F_a = %2 N: %3</source>
        <translation>die Radialkraft lässt sich aus den geschätzten F_t = %1 N und F_a = %2 N nicht bestimmen: %3</translation>
    </message>
    <message>
        <source>the friction ratio K_f = %1 found from F_t = %2 N and F_a = %3 N is negative: the friction on the rake face would push the chip down it</source>
        <translation>das aus F_t = %2 N und F_a = %3 N ermittelte Reibungsverhältnis K_f = %1 ist negativ: Die Reibung auf der Spanfläche würde den Span an ihr hinunterdrücken</translation>
    </message>
    <message>
        <source>samples: %1 calibration cuts; at least %2 are needed (the paper trained on 21)</source>
        <translation>Stichproben: %1 Kalibrierschnitte; mindestens %2 sind nötig (die Veröffentlichung trainierte mit 21)</translation>
    </message>
    <message>
        <source>the measured tangential force is not a finite number</source>
        <translation>die gemessene Tangentialkraft ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>the measured axial force is not a finite number</source>
        <translation>die gemessene Axialkraft ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>tangential network (eq. 11): %1</source>
        <translation>Netz für die Tangentialkraft (Gl. 11): %1</translation>
    </message>
    <message>
        <source>axial network (eq. 13): %1</source>
        <translation>Netz für die Axialkraft (Gl. 13): %1</translation>
    </message>
    <message>
        <source>the current–force model has no valid &quot;%1&quot;</source>
        <translation>das Strom-Kraft-Modell hat keinen gültigen Wert „%1“</translation>
    </message>
</context>
<context>
    <name>CuttingModels</name>
    <message>
        <source>%1 = %2 is outside the range %3 &lt; %1 &lt; %4 in which %5 is stated to hold</source>
        <translation>%1 = %2 liegt außerhalb des Bereichs %3 &lt; %1 &lt; %4, für den %5 als gültig angegeben ist</translation>
    </message>
    <message>
        <source>chip thickness h = f sin(kappa_r) = %1 mm is outside the range %2–%3 mm over which the Kienzle constants of this material were measured</source>
        <translation>die Spanungsdicke h = f sin(kappa_r) = %1 mm liegt außerhalb des Bereichs %2–%3 mm, in dem die Kienzle-Konstanten dieses Werkstoffs gemessen wurden</translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002)</source>
        <translation>Gl. 20 nach Li &amp; Du (2002)</translation>
    </message>
    <message>
        <source>lead angle [°]</source>
        <translation>Anstellwinkel [°]</translation>
    </message>
    <message>
        <source>depth of cut [mm]</source>
        <translation>Schnitttiefe [mm]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>Vorschub [mm/rev]</translation>
    </message>
    <message>
        <source>nose radius [mm]</source>
        <translation>Eckenradius [mm]</translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002) needs a nose radius larger than the feed, but r_n = %1 mm and f = %2 mm/rev</source>
        <translation>Gl. 20 nach Li &amp; Du (2002) erfordert einen Eckenradius größer als den Vorschub, aber r_n = %1 mm und f = %2 mm/rev</translation>
    </message>
    <message>
        <source>no force measurements given</source>
        <translation>keine Kraftmessungen angegeben</translation>
    </message>
    <message>
        <source>the measurements do not determine K_n and K_f (rank %1 of 2)</source>
        <translation>die Messungen bestimmen K_n und K_f nicht (Rang %1 von 2)</translation>
    </message>
    <message>
        <source>the fitted normal pressure K_n = %1 N/mm² is not positive: check the measured forces and the tool angles</source>
        <translation>der angepasste Normaldruck K_n = %1 N/mm² ist nicht positiv: prüfen Sie die gemessenen Kräfte und die Werkzeugwinkel</translation>
    </message>
</context>
<context>
    <name>DataFiles</name>
    <message>
        <source>cannot open the data file: %1</source>
        <translation>die Datendatei kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>not a valid JSON object: %1</source>
        <translation>kein gültiges JSON-Objekt: %1</translation>
    </message>
    <message>
        <source>expected format &quot;%1&quot; version 1</source>
        <translation>erwartet wird Format „%1“ Version 1</translation>
    </message>
    <message>
        <source>required value is missing</source>
        <translation>erforderlicher Wert fehlt</translation>
    </message>
    <message>
        <source>expected {&quot;value&quot;: number, &quot;source&quot;: key of &quot;sources&quot;}</source>
        <translation>erwartet: {&quot;value&quot;: Zahl, &quot;source&quot;: Schlüssel aus &quot;sources&quot;}</translation>
    </message>
    <message>
        <source>material &quot;%1&quot; lacks its id, modulus, density or Kienzle constants</source>
        <translation>dem Werkstoff „%1“ fehlen ID, E-Modul, Dichte oder Kienzle-Konstanten</translation>
    </message>
    <message>
        <source>a stiffness range needs 0 &lt; compliant &lt;= stiff, not %1 and %2</source>
        <translation>ein Steifigkeitsbereich braucht 0 &lt; nachgiebig &lt;= steif, nicht %1 und %2</translation>
    </message>
    <message>
        <source>a boring-bar material needs its type letters, modulus, Poisson&apos;s ratio and largest overhang ratio</source>
        <translation>ein Bohrstangenwerkstoff benötigt seine Kennbuchstaben, E-Modul, Querkontraktionszahl und größtes Auskragverhältnis</translation>
    </message>
</context>
<context>
    <name>DeviationModel</name>
    <message>
        <source>Feed and passive force from the rule of thumb Ff = %1 Fc, Fp = %2 Fc (%3): the material data give no feed or passive force constants. Calibrate the forces for accuracy.</source>
        <translation>Vorschub- und Passivkraft nach der Faustregel Ff = %1 Fc, Fp = %2 Fc (%3): Die Werkstoffdaten enthalten keine Konstanten für Vorschub- oder Passivkraft. Kalibrieren Sie die Kräfte für höhere Genauigkeit.</translation>
    </message>
    <message>
        <source>no source: zero</source>
        <translation>keine Quelle: null</translation>
    </message>
    <message>
        <source>Toolpost shortening not included: holder &quot;%1&quot; is not in the data library.</source>
        <translation>Stauchung des Werkzeugträgers nicht berücksichtigt: Halter „%1“ ist nicht in der Datenbibliothek.</translation>
    </message>
    <message>
        <source>Workpiece only: machine supports rigid, no toolpost or thermal term.</source>
        <translation>Nur Werkstück: Maschinenabstützungen starr, ohne Werkzeugträger- und Wärmeanteil.</translation>
    </message>
    <message>
        <source>unknown material &quot;%1&quot;; the data library has: %2</source>
        <translation>unbekannter Werkstoff „%1“; die Datenbibliothek enthält: %2</translation>
    </message>
    <message>
        <source>material &quot;%1&quot; has no Poisson&apos;s ratio in the data, which the shear deflection needs</source>
        <translation>für Werkstoff „%1“ ist in den Daten keine Querkontraktionszahl hinterlegt, die für die Schubverformung benötigt wird</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library and its ISO 5608 style letter (third character) gives no known entering angle</source>
        <translation>Halter „%1“ ist nicht in der Datenbibliothek, und sein Kennbuchstabe nach ISO 5608 (drittes Zeichen) ergibt keinen bekannten Einstellwinkel</translation>
    </message>
    <message>
        <source>the Li &amp; Du model needs the rake and inclination angles of the tool; the data give none for holder &quot;%1&quot; with insert &quot;%2&quot;: set tool.rake_deg and tool.inclination_deg</source>
        <translation>das Modell nach Li &amp; Du benötigt Span- und Neigungswinkel des Werkzeugs; die Daten enthalten keine für Halter „%1“ mit Wendeschneidplatte „%2“: setzen Sie tool.rake_deg und tool.inclination_deg</translation>
    </message>
    <message>
        <source>the force model needs a known material and holder</source>
        <translation>das Kraftmodell benötigt einen bekannten Werkstoff und Halter</translation>
    </message>
    <message>
        <source>there is no cutting pass; the deviation is that of the pass that finishes the features</source>
        <translation>es gibt keinen Schnitt; die Abweichung ist die des Schnitts, der die Formelemente fertig bearbeitet</translation>
    </message>
    <message>
        <source>unknown machine &quot;%1&quot;; the data library has: %2</source>
        <translation>unbekannte Maschine „%1“; die Datenbibliothek enthält: %2</translation>
    </message>
    <message>
        <source>the %1 clamping with these supports leaves the part free to move</source>
        <translation>bei der Aufspannung %1 ist das Teil mit diesen Abstützungen frei beweglich</translation>
    </message>
    <message>
        <source>Thermal drift not characterised for this machine: taken as zero.</source>
        <translation>Thermische Drift für diese Maschine nicht charakterisiert: als null angenommen.</translation>
    </message>
    <message>
        <source>the pass needs %1 kW of cutting power, more than the machine&apos;s %2 kW</source>
        <translation>der Schnitt benötigt %1 kW Schnittleistung, mehr als die %2 kW der Maschine</translation>
    </message>
    <message>
        <source>compliant</source>
        <translation>nachgiebige</translation>
    </message>
    <message>
        <source>stiff</source>
        <translation>steife</translation>
    </message>
    <message>
        <source>Spindle–chuck not measured: a radial spring of %1 N/µm at the chuck face, the %2 end of the published range %3–%4 N/µm (%5); no tilt of the chuck. A test-bar fit (Valiño et al. 2008 §III) replaces it.</source>
        <translation>Spindel–Futter nicht gemessen: eine radiale Feder von %1 N/µm an der Futterstirn, das %2 Ende des veröffentlichten Bereichs %3–%4 N/µm (%5); ohne Kippen des Futters. Eine Anpassung an einen Prüfstab (Valiño et al. 2008 §III) ersetzt sie.</translation>
    </message>
    <message>
        <source>Spindle–chuck neither measured nor in the data: taken as rigid, which is optimistic. Measure k1, k2, k3 (Valiño et al. 2008 §III).</source>
        <translation>Spindel–Futter weder gemessen noch in den Daten: als starr angenommen, was optimistisch ist. Messen Sie k1, k2, k3 (Valiño et al. 2008 §III).</translation>
    </message>
    <message>
        <source>%1 not measured and no published stiffness found: taken as a rigid pin, which is optimistic. The verdicts give the stiffness each tolerance needs of it.</source>
        <translation>%1 nicht gemessen und keine veröffentlichte Steifigkeit gefunden: als starres Lager angenommen, was optimistisch ist. Die Bewertungen nennen die Steifigkeit, die jede Toleranz von ihm braucht.</translation>
    </message>
    <message>
        <source>Headstock centre</source>
        <translation>Spindelstockspitze</translation>
    </message>
    <message>
        <source>Tailstock</source>
        <translation>Reitstock</translation>
    </message>
    <message>
        <source>given forces</source>
        <translation>vorgegebene Kräfte</translation>
    </message>
    <message>
        <source>Toolpost: the whole holder length (%1 mm) is taken in compression, an upper bound; enter the tool&apos;s overhang (the length out of the turret) to replace it.</source>
        <translation>Werkzeughalter: Die ganze Halterlänge (%1 mm) wird auf Druck gerechnet, eine obere Schranke; geben Sie die Auskraglänge des Werkzeugs (die Länge außerhalb des Revolvers) ein, um sie zu ersetzen.</translation>
    </message>
    <message>
        <source>the predicted deflection, %1 mm at z = %2 mm, is larger than the depth of cut %3 mm: the part would spring out of the cut, and a model linear in the forces of the nominal depth does not hold; support the part (tailstock, steady rest) or cut less</source>
        <translation>die vorhergesagte Durchbiegung, %1 mm bei z = %2 mm, ist größer als die Schnitttiefe %3 mm: Das Teil würde aus dem Schnitt federn, und ein in den Kräften der Nenntiefe lineares Modell gilt nicht; stützen Sie das Teil (Reitstock, Lünette) ab oder schneiden Sie weniger tief</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar in the data library</source>
        <translation>&quot;%1&quot; ist keine Bohrstange in der Datenbibliothek</translation>
    </message>
    <message>
        <source>the bar material of &quot;%1&quot; (type letter %2) is not in the data library: its stiffness is unknown</source>
        <translation>der Stangenwerkstoff von &quot;%1&quot; (Kennbuchstabe %2) ist nicht in der Datenbibliothek: seine Steifigkeit ist unbekannt</translation>
    </message>
    <message>
        <source>an overhang of %1 mm does not reach the bottom of the bore, %2 mm in from the right end face</source>
        <translation>eine Auskraglänge von %1 mm reicht nicht bis zum Grund der Bohrung, %2 mm von der rechten Stirnfläche</translation>
    </message>
    <message>
        <source>an overhang of %1 mm is longer than the bar &quot;%2&quot; itself (%3 mm)</source>
        <translation>eine Auskraglänge von %1 mm ist länger als die Stange &quot;%2&quot; selbst (%3 mm)</translation>
    </message>
    <message>
        <source>Boring bar %1: %2, Ø%3 mm, %4 mm overhang (L/D %5), E = %6 GPa (%7).</source>
        <translation>Bohrstange %1: %2, Ø%3 mm, %4 mm Auskraglänge (L/D %5), E = %6 GPa (%7).</translation>
    </message>
    <message>
        <source>The cutting edge&apos;s offset from the bar axis (the maker&apos;s f) not given: taken as the bar&apos;s radius, %1 mm, the least it can be; the twist of the bar and the moment of the feed force grow with it.</source>
        <translation>Versatz der Schneide von der Stangenachse (Maß f des Herstellers) nicht angegeben: als Radius der Stange angenommen, %1 mm, das Kleinstmögliche; die Verdrehung der Stange und das Moment der Vorschubkraft wachsen damit.</translation>
    </message>
    <message>
        <source>Boring bar %1 has a coolant bore the designation does not size: computed as a solid bar, which underestimates its deflection.</source>
        <translation>Bohrstange %1 hat eine Kühlmittelbohrung, deren Maße die Bezeichnung nicht angibt: als Vollstange berechnet, was ihre Durchbiegung unterschätzt.</translation>
    </message>
    <message>
        <source>No boring bar given: the bores are computed as if cut by the turning tool %1, without the bending of a bar, which in a bore is often the largest term.</source>
        <translation>Keine Bohrstange angegeben: die Bohrungen werden berechnet, als würden sie mit dem Drehwerkzeug %1 bearbeitet, ohne die Biegung einer Stange, die in einer Bohrung oft der größte Anteil ist.</translation>
    </message>
    <message>
        <source>%1, operation %2 of %3: the part held at its %4 end, z from that end.</source>
        <translation>%1, Aufspannung %2 von %3: das Teil am Ende %4 gespannt, z von diesem Ende.</translation>
    </message>
    <message>
        <source>The outer features later operations turn are still the stock, Ø%1 mm.</source>
        <translation>Die Außenformelemente, die spätere Aufspannungen drehen, sind noch Rohmaterial, Ø%1 mm.</translation>
    </message>
    <message>
        <source>The boring bar is taken as held rigidly in the turret: no stiffness of a bar clamp is known, so the bar&apos;s deflection is a lower bound.</source>
        <translation>Die Bohrstange gilt als starr im Revolver gespannt: keine Steifigkeit einer Stangenaufnahme ist bekannt, die Verformung der Stange ist daher eine untere Grenze.</translation>
    </message>
    <message>
        <source>The bores later operations cut are still solid material (no pre-drilled hole is assumed).</source>
        <translation>Die Bohrungen, die spätere Aufspannungen bearbeiten, sind noch Vollmaterial (keine Vorbohrung angenommen).</translation>
    </message>
    <message>
        <source>Collet: no published stiffness of a collet or of the spindle holding one was found, so it is taken as rigid at the collet&apos;s face, which is optimistic. The verdicts give the stiffness each tolerance needs of it.</source>
        <translation>Spannzange: Für eine Spannzange oder die Spindel mit Spannzange wurde keine veröffentlichte Steifigkeit gefunden; sie wird an ihrer Stirnseite als starr angenommen, was optimistisch ist. Die Bewertungen nennen die Steifigkeit, die jede Toleranz von ihr braucht.</translation>
    </message>
    <message>
        <source>Workpiece beam without the corrections for the root in the jaws and the shoulders: plain Timoshenko theory, up to about 10 % stiffer than a solid model where a chuck holds the part (docs/solid-fe.md).</source>
        <translation>Werkstückbalken ohne die Korrekturen für die Einspannung in den Backen und die Absätze: reine Timoshenko-Theorie, bis etwa 10 % steifer als ein Volumenmodell, wo ein Futter das Teil spannt (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Workpiece beam corrected from solid FE: built in %1 of its diameter inside the jaws, a hinge at each shoulder (docs/solid-fe.md).</source>
        <translation>Werkstückbalken nach Volumen-FE korrigiert: um das %1-Fache seines Durchmessers innerhalb der Backen eingespannt, ein Gelenk an jedem Absatz (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Workpiece beam corrected from solid FE: a hinge at each shoulder (docs/solid-fe.md).</source>
        <translation>Werkstückbalken nach Volumen-FE korrigiert: ein Gelenk an jedem Absatz (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Boring bar overhang not given: taken as the bore&apos;s depth and the program&apos;s clearance off the end face, %1 mm, the least that reaches; a longer overhang bends more.</source>
        <translation>Auskraglänge der Bohrstange nicht angegeben: als Tiefe der Bohrung und der Abstand des Programms von der Stirnfläche angenommen, %1 mm, das Mindeste, das hinreicht; eine größere Auskraglänge biegt sich stärker.</translation>
    </message>
    <message>
        <source>Ambient temperature not given (environment): taken as the characterisation&apos;s reference, %1 °C, so no drift from it.</source>
        <translation>Umgebungstemperatur nicht angegeben (environment): als Bezugstemperatur der Charakterisierung angenommen, %1 °C, also keine Drift durch sie.</translation>
    </message>
    <message>
        <source>there is no pass %1 (the project has %2)</source>
        <translation>es gibt keinen Schnitt %1 (das Projekt hat %2)</translation>
    </message>
    <message>
        <source>Time since the machine started not given (environment): taken as warmed through, %1 min (ten time constants), the largest drift of the size (not always of the form).</source>
        <translation>Zeit seit dem Start der Maschine nicht angegeben (environment): als durchgewärmt angenommen, %1 min (zehn Zeitkonstanten), die größte Drift des Maßes (nicht immer der Form).</translation>
    </message>
    <message>
        <source>Spindle–chuck tangential springs not measured: the chuck is taken as rigid tangentially (the radial springs are measured). A tangential deflection δ_t changes the machined radius by about δ_t²/2r only; give tangential_um in the test-bar fit to measure them.</source>
        <translation>Tangentiale Federn Spindel–Futter nicht gemessen: das Futter wird tangential als starr angenommen (die radialen Federn sind gemessen). Eine tangentiale Verformung δ_t ändert den gefertigten Radius nur um etwa δ_t²/2r; geben Sie tangential_um in der Prüfstab-Anpassung an, um sie zu messen.</translation>
    </message>
</context>
<context>
    <name>DriveReadings</name>
    <message>
        <source>%1 is not a finite number (a current from three phases is not, when a phase is negative or not finite)</source>
        <translation>%1 ist keine endliche Zahl (ein aus drei Phasen gebildeter Strom ist es nicht, wenn eine Phase negativ oder nicht endlich ist)</translation>
    </message>
    <message>
        <source>%1 = %2 is negative</source>
        <translation>%1 = %2 ist negativ</translation>
    </message>
    <message>
        <source>the spindle speed ω_s = %1 rad/s is not above zero: no cut</source>
        <translation>die Spindeldrehzahl ω_s = %1 rad/s ist nicht größer als null: kein Schnitt</translation>
    </message>
    <message>
        <source>the spindle current I_s = %1 A is below its idle current I_s0 = %2 A plus friction current ΔI_sf = %3 A, so the cutting current ΔI_s (eq. 10) would be negative: measure the idle and friction currents again at this speed</source>
        <translation>der Spindelmotorstrom I_s = %1 A liegt unter seinem Leerlaufstrom I_s0 = %2 A plus Reibstrom ΔI_sf = %3 A, sodass der Schnittstrom ΔI_s (Gl. 10) negativ wäre: Messen Sie Leerlauf- und Reibstrom bei dieser Drehzahl erneut</translation>
    </message>
    <message>
        <source>the feed current I_a = %1 A is below its idle current I_a0 = %2 A, so the cutting current ΔI_a would be negative: measure the idle current again at this feed speed</source>
        <translation>der Vorschubmotorstrom I_a = %1 A liegt unter seinem Leerlaufstrom I_a0 = %2 A, sodass der Schnittstrom ΔI_a negativ wäre: Messen Sie den Leerlaufstrom bei dieser Vorschubgeschwindigkeit erneut</translation>
    </message>
    <message>
        <source>the drive reading lacks the number &quot;%1&quot;</source>
        <translation>den Antriebsmesswerten fehlt die Zahl „%1“</translation>
    </message>
</context>
<context>
    <name>ExternalTools</name>
    <message>
        <source>&quot;%1&quot; is not on the PATH</source>
        <translation>„%1“ ist nicht im PATH</translation>
    </message>
    <message>
        <source>%1 is set to &quot;%2&quot;, which is not an executable file</source>
        <translation>%1 ist auf „%2“ gesetzt; das ist keine ausführbare Datei</translation>
    </message>
    <message>
        <source>%1 was not found: %2. Install it with: sudo apt install %3 (or run tools/bootstrap.sh), or set %4 to its executable.</source>
        <translation>%1 wurde nicht gefunden: %2. Installieren Sie es mit: sudo apt install %3 (oder führen Sie tools/bootstrap.sh aus), oder setzen Sie %4 auf seine ausführbare Datei.</translation>
    </message>
</context>
<context>
    <name>FeedScheduleText</name>
    <message>
        <source>top of the feed range</source>
        <translation>oberes Ende des Vorschubbereichs</translation>
    </message>
    <message>
        <source>the plan has no finishing pass</source>
        <translation>der Plan hat keinen Schlichtschnitt</translation>
    </message>
    <message>
        <source>Feeds from %1 to %2 mm/rev in steps of %3 mm/rev (the plan&apos;s feed range), each feature&apos;s the largest that holds its tolerances and the finishing pass&apos;s limits; the bores keep the programmed feed.</source>
        <translation>Vorschübe von %1 bis %2 mm/U in Schritten von %3 mm/U (der Vorschubbereich der Planung), für jedes Formelement der größte, der seine Toleranzen und die Grenzen des Schlichtschnitts hält; die Bohrungen behalten den programmierten Vorschub.</translation>
    </message>
</context>
<context>
    <name>FinishedExtent</name>
    <message>
        <source>%1 at z = %2 mm from r %3 to %4 mm</source>
        <translation>%1 bei z = %2 mm von r %3 bis %4 mm</translation>
    </message>
    <message>
        <source>z %1–%2 mm of %3</source>
        <translation>z %1–%2 mm von %3</translation>
    </message>
    <message>
        <source>not finished by this set-up&apos;s program, which leaves %1 as it was (see the program&apos;s warnings); on what it turns: %2</source>
        <translation>nicht fertig bearbeitet vom Programm dieser Aufspannung, das %1 unbearbeitet lässt (siehe die Warnungen des Programms); auf dem, was es dreht: %2</translation>
    </message>
</context>
<context>
    <name>GCode</name>
    <message>
        <source>No compensation: toleranced diameters at the middle of their zone</source>
        <translation>Keine Kompensation: tolerierte Durchmesser in der Mitte ihrer Toleranzzone</translation>
    </message>
    <message>
        <source>%1 offset %2 um on diameter</source>
        <translation>%1 Korrektur %2 um auf den Durchmesser</translation>
    </message>
    <message>
        <source>%1 profile corrected by the predicted deviation</source>
        <translation>%1 Kontur um die vorhergesagte Abweichung korrigiert</translation>
    </message>
    <message>
        <source>Compensated path: no feature needs a correction</source>
        <translation>Kompensierte Bahn: kein Formelement braucht eine Korrektur</translation>
    </message>
    <message>
        <source>Compensated: %1</source>
        <translation>Kompensiert: %1</translation>
    </message>
    <message>
        <source>vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>vc %1 m/min, f %2 mm/U, ap %3 mm</translation>
    </message>
    <message>
        <source>pass %1</source>
        <translation>Schnitt %1</translation>
    </message>
    <message>
        <source>passes %1-%2</source>
        <translation>Schnitte %1-%2</translation>
    </message>
    <message>
        <source>%1 roughing %2</source>
        <translation>%1 Schruppen %2</translation>
    </message>
    <message>
        <source>pass %1 finishing %2</source>
        <translation>Schnitt %1 Schlichten %2</translation>
    </message>
    <message>
        <source>%1, as chosen</source>
        <translation>%1, wie gewählt</translation>
    </message>
    <message>
        <source>%1, the control of machine %2</source>
        <translation>%1, die Steuerung der Maschine %2</translation>
    </message>
    <message>
        <source>%1: machine %2 has no CNC control in the data; choose the dialect of yours</source>
        <translation>%1: Maschine %2 hat in den Daten keine CNC-Steuerung; wählen Sie den Dialekt Ihrer Steuerung</translation>
    </message>
    <message>
        <source>TolTurn %1: %2</source>
        <translation>TolTurn %1: %2</translation>
    </message>
    <message>
        <source>Material %1, insert %2, holder %3, clamping %4</source>
        <translation>Werkstoff %1, Wendeschneidplatte %2, Halter %3, Aufspannung %4</translation>
    </message>
    <message>
        <source>Dialect: %1</source>
        <translation>Dialekt: %1</translation>
    </message>
    <message>
        <source>Conditions: %1</source>
        <translation>Schnittwerte: %1</translation>
    </message>
    <message>
        <source>%1, operation %2 of %3: the drawing&apos;s %4 end held; the right end face below is the free end of this set-up</source>
        <translation>%1, Aufspannung %2 von %3: Ende %4 der Zeichnung gespannt; die rechte Stirnfläche im folgenden Programm ist das freie Ende dieser Aufspannung</translation>
    </message>
    <message>
        <source>bore pass %1</source>
        <translation>Bohrschnitt %1</translation>
    </message>
    <message>
        <source>bore passes %1-%2</source>
        <translation>Bohrschnitte %1-%2</translation>
    </message>
    <message>
        <source>bore pass %1 finishing %2</source>
        <translation>Bohrschnitt %1 Schlichten %2</translation>
    </message>
    <message>
        <source>boring, roughing</source>
        <translation>Bohren, Schruppen</translation>
    </message>
    <message>
        <source>boring, finishing</source>
        <translation>Bohren, Schlichten</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>Schruppen</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>Schlichten</translation>
    </message>
    <message>
        <source>The bores are not in this program: the set-up has no boring bar (Set-up dock, Boring bar).</source>
        <translation>Die Bohrungen sind nicht in diesem Programm: Die Aufspannung hat keine Bohrstange (Dock Aufspannung, Bohrstange).</translation>
    </message>
    <message>
        <source>Tool %1: boring bar %2 (D%3 mm, overhang %4 mm), insert %5</source>
        <translation>Werkzeug %1: Bohrstange %2 (D%3 mm, Auskraglänge %4 mm), Wendeschneidplatte %5</translation>
    </message>
    <message>
        <source>The bores are not in this program: a centre holds the set-up&apos;s free end, so the boring bar cannot enter it. Bore them in a set-up held in the chuck alone.</source>
        <translation>Die Bohrungen sind nicht in diesem Programm: Eine Spitze hält das freie Ende der Aufspannung, die Bohrstange kann dort nicht einfahren. Bohren Sie sie in einer Aufspannung nur im Futter.</translation>
    </message>
    <message>
        <source>Finishing feed scheduled by feature (TolTurn feed schedule): %1</source>
        <translation>Schlichtvorschub je Formelement (TolTurn-Vorschubplan): %1</translation>
    </message>
    <message>
        <source>Roughing feed raised where a level cuts less than its depth, to the planned force (TolTurn feed schedule)</source>
        <translation>Schruppvorschub erhöht, wo eine Ebene weniger als ihre Schnitttiefe schneidet, bis zur geplanten Kraft (TolTurn-Vorschubplan)</translation>
    </message>
    <message>
        <source>Roughing feed not scheduled: the plan&apos;s settings give no feed range to stay within.</source>
        <translation>Schruppvorschub nicht geplant: die Planungsdaten nennen keinen Vorschubbereich, in dem er bleiben müsste.</translation>
    </message>
    <message>
        <source>The project has no finishing pass: its last pass (%1) is cut along the contour as the finishing pass, and the passes before it leave it its depth. Add a finishing pass.</source>
        <translation>Das Projekt hat keinen Schlichtschnitt: sein letzter Schnitt (%1) wird als Schlichtschnitt entlang der Kontur gefahren, und die Schnitte davor lassen ihm seine Schnitttiefe. Fügen Sie einen Schlichtschnitt hinzu.</translation>
    </message>
</context>
<context>
    <name>GCodeCommand</name>
    <message>
        <source>The turning program: the planned roughing passes and the finishing pass of the outer contour, nominal or compensated only where a tolerance needs it, for the machine&apos;s control (Fanuc/Haas, Sinumerik or LinuxCNC).</source>
        <translation>Das Drehprogramm: die geplanten Schruppschnitte und der Schlichtschnitt der Außenkontur, nominal oder nur dort kompensiert, wo eine Toleranz es verlangt, für die Steuerung der Maschine (Fanuc/Haas, Sinumerik oder LinuxCNC).</translation>
    </message>
    <message>
        <source>File to write; - for standard output.</source>
        <translation>Zu schreibende Datei; - für die Standardausgabe.</translation>
    </message>
    <message>
        <source>Correct the path where a tolerance needs it (offset or profile).</source>
        <translation>Die Bahn dort korrigieren, wo eine Toleranz es verlangt (Korrektur oder Kontur).</translation>
    </message>
    <message>
        <source>Control dialect: fanuc (also Haas), sinumerik or linuxcnc. Default: the machine&apos;s control.</source>
        <translation>Steuerungsdialekt: fanuc (auch Haas), sinumerik oder linuxcnc. Standard: die Steuerung der Maschine.</translation>
    </message>
    <message>
        <source>Nose radius: &apos;control&apos; programs the contour with G42, the bore with G41 (the control compensates), &apos;tip-path&apos; the path of the imaginary tool tip computed by TolTurn. Default: control.</source>
        <translation>Eckenradius: &apos;control&apos; programmiert die Kontur mit G42, die Bohrung mit G41 (die Steuerung kompensiert), &apos;tip-path&apos; die von TolTurn berechnete Bahn der theoretischen Schneidenspitze. Standard: control.</translation>
    </message>
    <message>
        <source>Project file.</source>
        <translation>Projektdatei.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE</source>
        <translation>geben Sie eine Projektdatei und -o DATEI an</translation>
    </message>
    <message>
        <source>--dialect: &apos;%1&apos; is not fanuc, sinumerik or linuxcnc</source>
        <translation>--dialect: &apos;%1&apos; ist weder fanuc noch sinumerik noch linuxcnc</translation>
    </message>
    <message>
        <source>--nose: &apos;%1&apos; is not control or tip-path</source>
        <translation>--nose: &apos;%1&apos; ist weder control noch tip-path</translation>
    </message>
    <message>
        <source>dialect %1</source>
        <translation>Dialekt %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Compensate with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Mit dem kompensieren, was von der Maschine aus ihren gemessenen Teilen gelernt wurde (learn --save).</translation>
    </message>
    <message>
        <source>feed schedule: %1 kept at the programmed %2 mm/rev: %3 is not held at any feed of the range (a case for compensation)</source>
        <translation>Vorschubplan: %1 bleibt beim programmierten Vorschub %2 mm/U: %3 wird bei keinem Vorschub des Bereichs gehalten (ein Fall für die Kompensation)</translation>
    </message>
    <message>
        <source>feed schedule: %1 at %2 mm/rev (programmed %3), limited by %4</source>
        <translation>Vorschubplan: %1 mit %2 mm/U (programmiert %3), begrenzt durch %4</translation>
    </message>
    <message>
        <source>feed schedule: finishing pass %1 s at the programmed feed, %2 s scheduled (%3 %)</source>
        <translation>Vorschubplan: Schlichtschnitt %1 s beim programmierten Vorschub, %2 s nach Plan (%3 %)</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>feed schedule: roughing passes %1 s at the programmed feed, %2 s scheduled (%3 %)</source>
        <translation>Vorschubplan: Schruppschnitte %1 s beim programmierten Vorschub, %2 s nach Plan (%3 %)</translation>
    </message>
    <message>
        <source>Cut each feature of the finishing pass at its own feed: the largest in the plan&apos;s feed range that holds its tolerances and the pass&apos;s limits. With --compensated, the features no feed holds keep the programmed feed and are compensated at it.</source>
        <translation>Jedes Formelement des Schlichtschnitts mit eigenem Vorschub drehen: dem größten im Vorschubbereich des Plans, der seine Toleranzen und die Grenzen des Schnitts einhält. Mit --compensated behalten die Formelemente, die kein Vorschub hält, den programmierten Vorschub und werden bei ihm kompensiert.</translation>
    </message>
    <message>
        <source>compensation: %1 %2, residual %3 → %4 µm</source>
        <translation>Kompensation: %1 %2, Restabweichung %3 → %4 µm</translation>
    </message>
    <message>
        <source>compensation: no tolerance needs a correction; the moves are the nominal program&apos;s</source>
        <translation>Kompensation: keine Toleranz braucht eine Korrektur; die Bewegungen sind die des nominalen Programms</translation>
    </message>
    <message>
        <source>program %1, checksum %2 (SHA-256, first 16 digits)</source>
        <translation>Programm %1, Prüfsumme %2 (SHA-256, erste 16 Stellen)</translation>
    </message>
</context>
<context>
    <name>HybridRbf</name>
    <message>
        <source>%1 input rows but %2 targets</source>
        <translation>%1 Eingabezeilen, aber %2 Zielwerte</translation>
    </message>
    <message>
        <source>%1 samples; the network needs at least 3</source>
        <translation>%1 Stichproben; das Netz braucht mindestens 3</translation>
    </message>
    <message>
        <source>an input or a target is not a finite number</source>
        <translation>eine Eingabe oder ein Zielwert ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>no network could be fitted to the samples</source>
        <translation>an die Stichproben ließ sich kein Netz anpassen</translation>
    </message>
</context>
<context>
    <name>ImportCommand</name>
    <message>
        <source>--%1 takes a number from 0, not &apos;%2&apos;</source>
        <translation>--%1 erwartet eine Zahl ab 0, nicht „%2“</translation>
    </message>
    <message>
        <source>no project written: the import has errors</source>
        <translation>es wurde kein Projekt geschrieben: der Import enthält Fehler</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Turn the part end for end (z = 0 at the other end).</source>
        <translation>Das Teil wenden (z = 0 am anderen Ende).</translation>
    </message>
    <message>
        <source>The body to import, from 0 (default: the largest).</source>
        <translation>Der zu importierende Körper, ab 0 (Standard: der größte).</translation>
    </message>
    <message>
        <source>The axis to turn about, from 0 (default: most revolved area).</source>
        <translation>Die Drehachse, ab 0 (Standard: die mit der größten Rotationsfläche).</translation>
    </message>
    <message>
        <source>The work material&apos;s id (default: %1).</source>
        <translation>Die ID des Werkstoffs (Standard: %1).</translation>
    </message>
    <message>
        <source>The machine&apos;s id (default: %1).</source>
        <translation>Die ID der Maschine (Standard: %1).</translation>
    </message>
    <message>
        <source>The STEP or IGES file.</source>
        <translation>Die STEP- oder IGES-Datei.</translation>
    </message>
    <message>
        <source>give one STEP or IGES file and -o PROJECT</source>
        <translation>geben Sie eine STEP- oder IGES-Datei und -o PROJEKT an</translation>
    </message>
    <message>
        <source>Write the project&apos;s part as a solid of revolution to a STEP file in mm (AP214), for CAD and CAM.</source>
        <translation>Das Teil des Projekts als Rotationskörper in eine STEP-Datei in mm (AP214) schreiben, für CAD und CAM.</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>Die Projektdatei.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE.step</source>
        <translation>geben Sie eine Projektdatei und -o DATEI.step an</translation>
    </message>
    <message>
        <source>%1: written</source>
        <translation>%1: geschrieben</translation>
    </message>
    <message>
        <source>cannot read back &apos;%1&apos;: %2</source>
        <translation>&apos;%1&apos; kann nicht zurückgelesen werden: %2</translation>
    </message>
    <message>
        <source>The project file to write (&apos;-&apos;: standard output).</source>
        <translation>Die zu schreibende Projektdatei (&apos;-&apos;: Standardausgabe).</translation>
    </message>
    <message>
        <source>--json and -o - would both write to standard output</source>
        <translation>--json und -o - würden beide auf die Standardausgabe schreiben</translation>
    </message>
    <message>
        <source>The STEP file to write (&apos;-&apos;: standard output).</source>
        <translation>Die zu schreibende STEP-Datei (&apos;-&apos;: Standardausgabe).</translation>
    </message>
    <message>
        <source>%1: written, part &quot;%2&quot;, %3 mm long, %4 outer and %5 inner features, %6</source>
        <translation>%1: geschrieben, Teil „%2“, %3 mm lang, %4 äußere und %5 innere Formelemente, %6</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Report the progress on standard error, as lines &quot;progress F&quot; with F from 0 to 1.</source>
        <translation>Den Fortschritt auf der Standardfehlerausgabe melden, als Zeilen „progress F“ mit F von 0 bis 1.</translation>
    </message>
    <message>
        <source>Turn a STEP (.step, .stp) or IGES (.iges, .igs) part into a new project: the outer and inner contour in mm, z = 0 at the left end; flats and keyways become milled features, other features that are not turned (cross holes) are listed as warnings.</source>
        <translation>Ein STEP- (.step, .stp) oder IGES-Teil (.iges, .igs) in ein neues Projekt umwandeln: die Außen- und Innenkontur in mm, z = 0 am linken Ende; Abflachungen und Passfedernuten werden zu gefrästen Formelementen, andere nicht gedrehte Formelemente (Querbohrungen) werden als Warnungen aufgeführt.</translation>
    </message>
    <message>
        <source>a choice is three whole numbers &quot;SOLID AXIS FLIP&quot; (SOLID and AXIS from 0, -1 for the default; FLIP 0 or 1), not &apos;%1&apos;</source>
        <translation>eine Wahl besteht aus drei ganzen Zahlen &quot;SOLID AXIS FLIP&quot; (SOLID und AXIS ab 0, -1 für die Vorgabe; FLIP 0 oder 1), nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>With --json: read the file once, print each result as one line, then extract again for each line &quot;SOLID AXIS FLIP&quot; on standard input, until it ends.</source>
        <translation>Mit --json: die Datei einmal lesen, jedes Ergebnis als eine Zeile ausgeben und dann für jede Zeile &quot;SOLID AXIS FLIP&quot; der Standardeingabe erneut extrahieren, bis diese endet.</translation>
    </message>
    <message>
        <source>--choose needs --json and a project file (-o PROJECT)</source>
        <translation>--choose braucht --json und eine Projektdatei (-o PROJECT)</translation>
    </message>
    <message>
        <source>--material: unknown material &quot;%1&quot;; the materials are: %2</source>
        <translation>--material: unbekannter Werkstoff „%1“; die Werkstoffe sind: %2</translation>
    </message>
    <message>
        <source>--machine: unknown machine &quot;%1&quot;; the machines are: %2</source>
        <translation>--machine: unbekannte Maschine „%1“; die Maschinen sind: %2</translation>
    </message>
</context>
<context>
    <name>InputBounds</name>
    <message>
        <source>%1 is beyond what TolTurn computes with: at most %2%3</source>
        <translation>%1 liegt jenseits dessen, womit TolTurn rechnet: höchstens %2%3</translation>
    </message>
    <message>
        <source>holds %1 entries, more than the %2 TolTurn computes with</source>
        <translation>enthält %1 Einträge, mehr als die %2, mit denen TolTurn rechnet</translation>
    </message>
</context>
<context>
    <name>InsertCodes</name>
    <message>
        <source>insert code &quot;%1&quot;: %2</source>
        <translation>Bezeichnung der Wendeschneidplatte „%1“: %2</translation>
    </message>
    <message>
        <source>not an ISO 1832 designation (four letters, then size, thickness and corner digits, as in CNMG 120408)</source>
        <translation>keine Bezeichnung nach ISO 1832 (vier Buchstaben, dann Ziffern für Größe, Dicke und Ecke, wie in CNMG 120408)</translation>
    </message>
    <message>
        <source>position 1 (shape) &apos;%1&apos; is not one of %2</source>
        <translation>Stelle 1 (Form): „%1“ ist keiner der Werte %2</translation>
    </message>
    <message>
        <source>position 2 (clearance angle) &apos;%1&apos; is not one of %2</source>
        <translation>Stelle 2 (Freiwinkel): „%1“ ist keiner der Werte %2</translation>
    </message>
    <message>
        <source>position 3 (tolerance class) &apos;%1&apos; is not one of %2</source>
        <translation>Stelle 3 (Toleranzklasse): „%1“ ist keiner der Werte %2</translation>
    </message>
    <message>
        <source>position 4 (type) &apos;%1&apos; is not one of %2</source>
        <translation>Stelle 4 (Typ): „%1“ ist keiner der Werte %2</translation>
    </message>
    <message>
        <source>position 5 (size) &apos;%1&apos; is not a standard cutting-edge length for shape %2</source>
        <translation>Stelle 5 (Größe): „%1“ ist keine genormte Schneidenlänge für Form %2</translation>
    </message>
    <message>
        <source>position 6 (thickness) &apos;%1&apos; is not an ISO 1832 thickness symbol</source>
        <translation>Stelle 6 (Dicke): „%1“ ist kein Dickenkennzeichen nach ISO 1832</translation>
    </message>
    <message>
        <source>position 7 of a round insert is M0 or 00, not &apos;%1&apos;</source>
        <translation>Stelle 7 einer runden Wendeschneidplatte ist M0 oder 00, nicht „%1“</translation>
    </message>
    <message>
        <source>position 7 (corner radius) &apos;%1&apos; gives a sharp corner, which turning inserts of shape %2 do not have in TolTurn&apos;s models</source>
        <translation>Stelle 7 (Eckenradius): „%1“ ergibt eine scharfe Ecke, die Drehplatten der Form %2 in den Modellen von TolTurn nicht haben</translation>
    </message>
</context>
<context>
    <name>Iso286</name>
    <message>
        <source>hole</source>
        <translation>Bohrung</translation>
    </message>
    <message>
        <source>shaft</source>
        <translation>Welle</translation>
    </message>
    <message>
        <source>the nominal size is not a finite number</source>
        <translation>das Nennmaß ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>0 mm is not a nominal size: the first range of ISO 286 is above 0 up to and including 3 mm</source>
        <translation>0 mm ist kein Nennmaß: der erste Nennmaßbereich der ISO 286 reicht von über 0 bis einschließlich 3 mm</translation>
    </message>
    <message>
        <source>the nominal size must be above 0 mm, but is %1 mm</source>
        <translation>das Nennmaß muss größer als 0 mm sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>%1 mm is above 3150 mm, the largest nominal size of ISO 286</source>
        <translation>%1 mm liegt über 3150 mm, dem größten Nennmaß der ISO 286</translation>
    </message>
    <message>
        <source>%1 is given by ISO 286-1 only for nominal sizes up to and including 500 mm, not for %2 mm</source>
        <translation>%1 ist in ISO 286-1 nur für Nennmaße bis einschließlich 500 mm angegeben, nicht für %2 mm</translation>
    </message>
    <message>
        <source>%1 shall not be used for nominal sizes up to and including 1 mm (ISO 286-1 Table 1), but the size is %2 mm</source>
        <translation>%1 darf für Nennmaße bis einschließlich 1 mm nicht verwendet werden (ISO 286-1 Tabelle 1), das Nennmaß beträgt aber %2 mm</translation>
    </message>
    <message>
        <source>%1 above 500 mm is given by ISO 286-1 for experimental use only (size %2 mm)</source>
        <translation>%1 über 500 mm ist in ISO 286-1 nur zur versuchsweisen Anwendung angegeben (Nennmaß %2 mm)</translation>
    </message>
    <message>
        <source>hole %1 is not defined: ISO 286-1 forms %2 up to IT%3 as ES = -ei + Δ, and tabulates Δ only for IT3 to IT8</source>
        <translation>Bohrung %1 ist nicht definiert: ISO 286-1 bildet %2 bis IT%3 als ES = -ei + Δ und tabelliert Δ nur für IT3 bis IT8</translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 gives K above IT8 only for nominal sizes up to and including 3 mm</source>
        <translation>Bohrung %1 ist für ein Nennmaß von %2 mm nicht definiert: ISO 286-1 gibt K über IT8 nur für Nennmaße bis einschließlich 3 mm an</translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 says N above IT8 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation>Bohrung %1 ist für ein Nennmaß von %2 mm nicht definiert: nach ISO 286-1 darf N über IT8 für Nennmaße bis einschließlich 1 mm nicht verwendet werden</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 says the fundamental deviations %4 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation>%1 %2 ist für ein Nennmaß von %3 mm nicht definiert: nach ISO 286-1 dürfen die Grundabmaße %4 für Nennmaße bis einschließlich 1 mm nicht verwendet werden</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives the fundamental deviation %4 only above %5 mm up to and including %6 mm</source>
        <translation>%1 %2 ist für ein Nennmaß von %3 mm nicht definiert: ISO 286-1 gibt das Grundabmaß %4 nur über %5 mm bis einschließlich %6 mm an</translation>
    </message>
    <message>
        <source>%1 %2 is not defined: ISO 286-1 tabulates %3 only for the grades IT%4 to IT%5 (the symmetric %6 covers every grade)</source>
        <translation>%1 %2 ist nicht definiert: ISO 286-1 tabelliert %3 nur für die Toleranzgrade IT%4 bis IT%5 (das symmetrische %6 deckt jeden Grad ab)</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives %4 only up to and including 500 mm</source>
        <translation>%1 %2 ist für ein Nennmaß von %3 mm nicht definiert: ISO 286-1 gibt %4 nur bis einschließlich 500 mm an</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives j8 only up to and including 3 mm</source>
        <translation>%1 %2 ist für ein Nennmaß von %3 mm nicht definiert: ISO 286-1 gibt j8 nur bis einschließlich 3 mm an</translation>
    </message>
    <message>
        <source>the tolerance class is empty; write a fundamental deviation letter and a tolerance grade, such as H7 or g6</source>
        <translation>die Toleranzklasse ist leer; geben Sie einen Grundabmaß-Buchstaben und einen Toleranzgrad an, etwa H7 oder g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tolerance class: write a fundamental deviation letter and a tolerance grade, such as H7, g6 or js6</source>
        <translation>„%1“ ist keine Toleranzklasse: geben Sie einen Grundabmaß-Buchstaben und einen Toleranzgrad an, etwa H7, g6 oder js6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; mixes upper and lower case in &quot;%2&quot;: hole letters are upper case (H7), shaft letters lower case (g6)</source>
        <translation>„%1“ mischt Groß- und Kleinbuchstaben in „%2“: Buchstaben für Bohrungen werden groß geschrieben (H7), für Wellen klein (g6)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not a fundamental deviation of ISO 286-1; the %3 letters are %4</source>
        <translation>„%1“: „%2“ ist kein Grundabmaß nach ISO 286-1; die Buchstaben für %3 sind %4</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: IT%2 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation>„%1“: IT%2 ist kein Grundtoleranzgrad; die Grade sind IT01, IT0 und IT1 bis IT18</translation>
    </message>
    <message>
        <source>IT%1 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation>IT%1 ist kein Grundtoleranzgrad; die Grade sind IT01, IT0 und IT1 bis IT18</translation>
    </message>
    <message>
        <source>%1 is a shaft class; the first class of a fit is the hole, written in upper case (H7)</source>
        <translation>%1 ist eine Wellenklasse; die erste Klasse einer Passung ist die der Bohrung, in Großbuchstaben geschrieben (H7)</translation>
    </message>
    <message>
        <source>%1 is a hole class; the second class of a fit is the shaft, written in lower case (g6)</source>
        <translation>%1 ist eine Bohrungsklasse; die zweite Klasse einer Passung ist die der Welle, in Kleinbuchstaben geschrieben (g6)</translation>
    </message>
    <message>
        <source>clearance</source>
        <translation>Spielpassung</translation>
    </message>
    <message>
        <source>transition</source>
        <translation>Übergangspassung</translation>
    </message>
    <message>
        <source>interference</source>
        <translation>Übermaßpassung</translation>
    </message>
    <message>
        <source>the designation is empty; write one such as 50 H7, Ø50 g6 or 50 H7/g6</source>
        <translation>die Bezeichnung ist leer; geben Sie eine an, etwa 50 H7, Ø50 g6 oder 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the diameter sign must be followed by the nominal size, as in Ø50 H7</source>
        <translation>„%1“: auf das Durchmesserzeichen muss das Nennmaß folgen, wie in Ø50 H7</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no tolerance class; write one after the nominal size, such as 50 H7 or 50 H7/g6</source>
        <translation>„%1“ hat keine Toleranzklasse; geben Sie sie nach dem Nennmaß an, etwa 50 H7 oder 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a designation: a fit is a hole class, a slash and a shaft class, as in 50 H7/g6</source>
        <translation>„%1“ ist keine Bezeichnung: eine Passung besteht aus einer Bohrungsklasse, einem Schrägstrich und einer Wellenklasse, wie in 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: a fit is written hole class first (upper case), then the shaft class (lower case), as in 50 H7/g6</source>
        <translation>„%1“: bei einer Passung steht die Bohrungsklasse zuerst (Großbuchstaben), dann die Wellenklasse (Kleinbuchstaben), wie in 50 H7/g6</translation>
    </message>
    <message>
        <source>the designation &quot;%1&quot; names %2 mm, but %3 mm was given separately</source>
        <translation>die Bezeichnung „%1“ nennt %2 mm, separat angegeben wurden aber %3 mm</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no nominal size; write it in the designation (50 H7) or give it separately</source>
        <translation>„%1“ hat kein Nennmaß; geben Sie es in der Bezeichnung (50 H7) oder separat an</translation>
    </message>
</context>
<context>
    <name>JsonReading</name>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>true</source>
        <translation>true</translation>
    </message>
    <message>
        <source>false</source>
        <translation>false</translation>
    </message>
    <message>
        <source>the number %1</source>
        <translation>die Zahl %1</translation>
    </message>
    <message>
        <source>the text &quot;%1&quot;</source>
        <translation>der Text „%1“</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>eine Liste</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>this field is required but missing</source>
        <translation>dieses Feld ist erforderlich, fehlt aber</translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation>erwartet: %1, gefunden: %2</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>eine ganze Zahl</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>ein Text</translation>
    </message>
    <message>
        <source>unknown %1 &quot;%2&quot;; expected one of: %3</source>
        <translation>unbekannter Wert „%2“ für %1; erwartet wird einer von: %3</translation>
    </message>
    <message>
        <source>unknown field, kept as it is</source>
        <translation>unbekanntes Feld, unverändert beibehalten</translation>
    </message>
</context>
<context>
    <name>LearnCommand</name>
    <message>
        <source>The machine to learn.</source>
        <translation>Die zu lernende Maschine.</translation>
    </message>
    <message>
        <source>The store: an SQLite file, or postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).</source>
        <translation>Der Speicher: eine SQLite-Datei oder postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (Vorgabe: %1).</translation>
    </message>
    <message>
        <source>gcv (default) or bic: when the network stops growing.</source>
        <translation>gcv (Vorgabe) oder bic: wann das Netz aufhört zu wachsen.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Das Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <source>give --machine ID, and --criterion gcv or bic</source>
        <translation>geben Sie --machine ID an, und --criterion gcv oder bic</translation>
    </message>
    <message>
        <source>%1: %2 parts, %3 measured points</source>
        <translation>%1: %2 Teile, %3 Messpunkte</translation>
    </message>
    <message>
        <source>  geometric error: %1 µm per mm of diameter, %2 µm per mm along z (taper), %3 µm offset</source>
        <translation>  geometrischer Fehler: %1 µm je mm Durchmesser, %2 µm je mm längs z (Konizität), %3 µm Versatz</translation>
    </message>
    <message>
        <source>  network: %1 of %2 nodes kept (radius scale %3), leave-one-out RMS %4 µm</source>
        <translation>  Netz: %1 von %2 Knoten behalten (Radiusfaktor %3), Leave-one-out-RMS %4 µm</translation>
    </message>
    <message>
        <source>  parts predicted without having been learned from (leave one part out): physics alone %1 µm RMS, physics + learned %2 µm RMS</source>
        <translation>  Teile vorhergesagt, ohne aus ihnen gelernt zu haben (ein Teil weggelassen): nur Physik %1 µm RMS, Physik + Gelerntes %2 µm RMS</translation>
    </message>
    <message>
        <source>Keep what was learned in the store as the machine&apos;s model, for the commands&apos; --learned.</source>
        <translation>Das Gelernte im Speicher als Modell der Maschine behalten, für --learned der Befehle.</translation>
    </message>
    <message>
        <source>kept as the model of %1 (number %2) in %3</source>
        <translation>als Modell von %1 (Nummer %2) in %3 behalten</translation>
    </message>
    <message>
        <source>nothing has been learned of %1 yet: run &apos;learn --machine %1 --save&apos;</source>
        <translation>von %1 wurde noch nichts gelernt: führen Sie „learn --machine %1 --save“ aus</translation>
    </message>
    <message>
        <source>%1 has %2</source>
        <translation>%1 hat %2</translation>
    </message>
    <message>
        <source>forces from motor currents: %1 calibration cuts; leaving one out, F_t to %2 N RMS, F_a to %3 N RMS</source>
        <translation>Kräfte aus Motorströmen: %1 Kalibrierschnitte; bei Weglassen je eines Schnitts F_t auf %2 N RMS, F_a auf %3 N RMS</translation>
    </message>
    <message>
        <source>Cuts with motor currents and dynamometer forces (CSV): parts that carry their drives&apos; readings then learn from forces estimated from their motor currents (Li &amp; Du eq. 7–19).</source>
        <translation>Schnitte mit Motorströmen und Dynamometerkräften (CSV): Teile mit Messwerten ihrer Antriebe lernen dann aus Kräften, die aus ihren Motorströmen geschätzt werden (Li &amp; Du Gl. 7–19).</translation>
    </message>
    <message>
        <source>%1 of %2 parts learned from forces estimated from their motor currents</source>
        <translation>%1 von %2 Teilen lernten aus Kräften, die aus ihren Motorströmen geschätzt wurden</translation>
    </message>
    <message>
        <source>  learned at: %1</source>
        <translation>  gelernt bei: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
</context>
<context>
    <name>LearnedModelJson</name>
    <message>
        <source>the learned model has no valid &quot;%1&quot;</source>
        <translation>das gelernte Modell hat kein gültiges „%1“</translation>
    </message>
</context>
<context>
    <name>MachineLearning</name>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>%1, model %2, %3 parts</source>
        <translation>%1, Modell %2, %3 Teile</translation>
    </message>
    <message>
        <source>the model %1 of %2 is damaged: %3</source>
        <translation>das Modell %1 von %2 ist beschädigt: %3</translation>
    </message>
    <message>
        <source>the project snapshot of part %1 does not read</source>
        <translation>der Projektstand von Teil %1 lässt sich nicht lesen</translation>
    </message>
    <message>
        <source>the physics model cannot compute the snapshot of part %1</source>
        <translation>das Physikmodell kann den Projektstand von Teil %1 nicht berechnen</translation>
    </message>
    <message>
        <source>as learned from its measured parts (%1, learned %2 UTC): parts not learned from were predicted to %3 µm RMS, the physics alone to %4 µm; its stiffness range is not used</source>
        <translation>wie aus ihren gemessenen Teilen gelernt (%1, gelernt %2 UTC): nicht zum Lernen verwendete Teile wurden auf %3 µm RMS vorhergesagt, von der Physik allein auf %4 µm; ihr Steifigkeitsbereich wird nicht verwendet</translation>
    </message>
    <message>
        <source>%1 with %2: %3</source>
        <translation>%1 mit %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n stored part(s)</source>
        <translation>
            <numerusform>%n gespeichertes Teil</numerusform>
            <numerusform>%n gespeicherte Teile</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n usable point(s)</source>
        <translation>
            <numerusform>%n verwendbarer Punkt</numerusform>
            <numerusform>%n verwendbare Punkte</numerusform>
        </translation>
    </message>
    <message>
        <source>part %1 is left out: its project was computed against another characterisation of the machine than the newest part %2, and a model learns what one physics misses</source>
        <translation>Teil %1 bleibt außen vor: sein Projekt wurde mit einer anderen Charakterisierung der Maschine berechnet als das neueste Teil %2, und ein Modell lernt, was eine Physik verfehlt</translation>
    </message>
    <message>
        <source>%1 was learned against another characterisation of %2 than this project&apos;s (its springs, supports or thermal drift differ): what it learned is what that physics missed, not this one. Learn again from parts cut with this characterisation, or predict without it</source>
        <translation>%1 wurde mit einer anderen Charakterisierung von %2 gelernt als der dieses Projekts (ihre Federn, Auflager oder Wärmedrift unterscheiden sich): was es gelernt hat, ist, was jene Physik verfehlte, nicht diese. Lernen Sie neu aus Teilen, die mit dieser Charakterisierung gefertigt wurden, oder sagen Sie ohne es voraus</translation>
    </message>
    <message>
        <source>part %1 is left out: it is part %2 stored again (the same project, time and points)</source>
        <translation>Teil %1 bleibt außen vor: es ist Teil %2, noch einmal gespeichert (dasselbe Projekt, dieselbe Zeit, dieselben Punkte)</translation>
    </message>
    <message>
        <source>the measured points lie on one %1</source>
        <translation>die gemessenen Punkte liegen auf einem einzigen Wert: %1</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>position z</source>
        <translation>Position z</translation>
    </message>
    <message>
        <source>the measured points&apos; diameters and positions z move together (correlation %1)</source>
        <translation>Durchmesser und Positionen z der gemessenen Punkte ändern sich gemeinsam (Korrelation %1)</translation>
    </message>
    <message>
        <source>%1: the geometric error&apos;s split between diameter and z is not determined, and what was learned holds along the measured points only; measure features of other diameters at other z</source>
        <translation>%1: die Aufteilung des geometrischen Fehlers auf Durchmesser und z ist nicht bestimmt, und das Gelernte gilt nur entlang der gemessenen Punkte; messen Sie Formelemente anderer Durchmesser an anderen z</translation>
    </message>
    <message>
        <source>What was learned predicts parts it did not learn from worse than the physics alone (%1 against %2 µm RMS): it adds error here. Learn from more parts, or predict without it</source>
        <translation>Das Gelernte sagt Teile, aus denen es nicht gelernt hat, schlechter voraus als die Physik allein (%1 gegenüber %2 µm RMS): es fügt hier Fehler hinzu. Aus mehr Teilen lernen oder ohne es vorhersagen</translation>
    </message>
</context>
<context>
    <name>MeasuredParts</name>
    <message>
        <source>the part&apos;s profile has no feature &quot;%1&quot;</source>
        <translation>das Profil des Teils hat kein Element „%1“</translation>
    </message>
    <message>
        <source>z = %1 mm is not on feature %2 (z from %3 to %4 mm)</source>
        <translation>z = %1 mm liegt nicht auf Element %2 (z von %3 bis %4 mm)</translation>
    </message>
    <message>
        <source>a diameter of %1 mm does not fit feature %2 (Ø%3 to Ø%4 mm)</source>
        <translation>ein Durchmesser von %1 mm passt nicht zu Element %2 (Ø%3 bis Ø%4 mm)</translation>
    </message>
    <message>
        <source>a radial deviation of %1 mm is beyond the ±%2 mm of a turned part</source>
        <translation>eine radiale Abweichung von %1 mm liegt außerhalb der ±%2 mm eines Drehteils</translation>
    </message>
    <message>
        <source>the machine the part was cut on is not given</source>
        <translation>die Maschine, auf der das Teil gefertigt wurde, ist nicht angegeben</translation>
    </message>
    <message>
        <source>the time of measurement is not given</source>
        <translation>der Zeitpunkt der Messung ist nicht angegeben</translation>
    </message>
    <message>
        <source>the time since start must be from 0 to %1 min, not %2</source>
        <translation>die Zeit seit dem Start muss zwischen 0 und %1 min liegen, nicht %2</translation>
    </message>
    <message>
        <source>the ambient temperature must be from %1 to %2 °C, not %3</source>
        <translation>die Umgebungstemperatur muss zwischen %1 und %2 °C liegen, nicht %3</translation>
    </message>
    <message>
        <source>the project the part was cut from is not a valid project%1</source>
        <translation>das Projekt, aus dem das Teil gefertigt wurde, ist kein gültiges Projekt%1</translation>
    </message>
    <message>
        <source>the part has no measured point</source>
        <translation>das Teil hat keinen Messpunkt</translation>
    </message>
    <message>
        <source>a CMM point needs finite x and y (x = %1, y = %2 mm)</source>
        <translation>ein KMG-Punkt braucht endliche Werte für x und y (x = %1, y = %2 mm)</translation>
    </message>
    <message>
        <source>a CMM point at radius %1 mm is not on feature %2 (R%3 to R%4 mm)</source>
        <translation>ein KMG-Punkt bei Radius %1 mm liegt nicht auf Merkmal %2 (R%3 bis R%4 mm)</translation>
    </message>
    <message>
        <source>the part was cut on %1, but its project is planned for %2: set the project&apos;s machine to %1 as it was cut, then store the part</source>
        <translation>das Teil wurde auf %1 gefertigt, sein Projekt ist aber für %2 geplant: die Maschine des Projekts auf %1 setzen, wie gefertigt, dann das Teil speichern</translation>
    </message>
    <message>
        <source>a CMM point&apos;s radius %1 mm is not √(x² + y²) = %2 mm</source>
        <translation>der Radius %1 mm eines KMG-Punkts ist nicht √(x² + y²) = %2 mm</translation>
    </message>
</context>
<context>
    <name>MeasuredResiduals</name>
    <message>
        <source>part %1 is left out: its project snapshot does not read</source>
        <translation>Teil %1 bleibt außen vor: sein Projektstand lässt sich nicht lesen</translation>
    </message>
    <message>
        <source>part %1 is left out: the physics model cannot compute its project</source>
        <translation>Teil %1 bleibt außen vor: das physikalische Modell kann sein Projekt nicht berechnen</translation>
    </message>
    <message>
        <source>%1 measured points; learning needs at least 3</source>
        <translation>%1 Messpunkte; das Lernen braucht mindestens 3</translation>
    </message>
    <message>
        <source>%1 measured part(s); leaving one out needs at least 2</source>
        <translation>%1 gemessene(s) Teil(e); das Weglassen eines Teils braucht mindestens 2</translation>
    </message>
    <message>
        <source>The predicted radius errors include what was learned from measured parts (%1): the machine&apos;s measured behaviour replaces its stiffness range.</source>
        <translation>Die vorhergesagten Radiusfehler enthalten, was aus gemessenen Teilen gelernt wurde (%1): das gemessene Verhalten der Maschine ersetzt ihren Steifigkeitsbereich.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>Teil %1: %2</translation>
    </message>
    <message>
        <source>part %1: its forces are the physics model&apos;s, not estimated from its motor currents</source>
        <translation>Teil %1: Seine Kräfte stammen aus dem Physikmodell, nicht aus seinen Motorströmen geschätzt</translation>
    </message>
    <message>
        <source>part %1: %2 of its %3 points are not compared with the physics (on a face or on a feature its set-up&apos;s passes do not turn)</source>
        <translation>Teil %1: %2 seiner %3 Punkte werden nicht mit der Physik verglichen (auf einer Planfläche oder auf einem Formelement, das die Schnitte seiner Aufspannung nicht drehen)</translation>
    </message>
    <message>
        <source>part %1: its motor currents are of the first set-up&apos;s finishing cut; %2 points cut in a later set-up are compared at the force model&apos;s forces</source>
        <translation>Teil %1: seine Motorströme gehören zum Schlichtschnitt der ersten Aufspannung; %2 Punkte, die in einer späteren Aufspannung geschnitten wurden, werden mit den Kräften des Kraftmodells verglichen</translation>
    </message>
    <message>
        <source>%1 %2 (measured parts %3)</source>
        <translation>%1 %2 (gemessene Teile %3)</translation>
    </message>
    <message>
        <source>spindle speed [rpm]</source>
        <translation>Spindeldrehzahl [1/min]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>Vorschub [mm/U]</translation>
    </message>
    <message>
        <source>with part %1 left out: %2</source>
        <translation>ohne Teil %1: %2</translation>
    </message>
    <message>
        <source>This plan is cut at other conditions than the parts the learned model was measured on: %1. There what was learned is extrapolated (a condition the parts did not vary is taken to have no effect, and the network&apos;s correction fades away from the conditions it learned at); measure parts cut at these conditions</source>
        <translation>Dieser Plan wird unter anderen Bedingungen geschnitten als die Teile, an denen das gelernte Modell gemessen wurde: %1. Dort wird das Gelernte extrapoliert (eine Bedingung, die die Teile nicht variierten, gilt als wirkungslos, und die Korrektur des Netzes klingt fern der gelernten Bedingungen ab); messen Sie Teile, die unter diesen Bedingungen geschnitten wurden</translation>
    </message>
    <message>
        <source>spindle speed %1 rpm, feed %2 mm/rev, passive force %3 N, %4 min since start, ambient %5 °C, diameter %6 mm, z %7 mm</source>
        <translation>Spindeldrehzahl %1 1/min, Vorschub %2 mm/U, Passivkraft %3 N, %4 min seit Start, Umgebung %5 °C, Durchmesser %6 mm, z %7 mm</translation>
    </message>
    <message>
        <source>passive force [N]</source>
        <translation>Passivkraft [N]</translation>
    </message>
    <message>
        <source>time since start [min]</source>
        <translation>Zeit seit Start [min]</translation>
    </message>
    <message>
        <source>ambient temperature [°C]</source>
        <translation>Umgebungstemperatur [°C]</translation>
    </message>
</context>
<context>
    <name>MeasurementCsv</name>
    <message>
        <source>a line needs one of diameter_mm, radial_deviation_um, or x_mm and y_mm (a CMM point)</source>
        <translation>eine Zeile braucht diameter_mm, radial_deviation_um oder x_mm und y_mm (einen KMG-Punkt)</translation>
    </message>
</context>
<context>
    <name>MeasurementFiles</name>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>the header lacks the column &quot;%1&quot;; it needs %2</source>
        <translation>in der Kopfzeile fehlt die Spalte „%1“; benötigt werden %2</translation>
    </message>
    <message>
        <source>%1 must be a number%2, not &quot;%3&quot;</source>
        <translation>%1 muss eine Zahl%2 sein, nicht „%3“</translation>
    </message>
    <message>
        <source> above zero</source>
        <translation> größer als null</translation>
    </message>
    <message>
        <source>the file has no header line</source>
        <translation>die Datei hat keine Kopfzeile</translation>
    </message>
    <message>
        <source>the file has no measurement</source>
        <translation>die Datei enthält keine Messung</translation>
    </message>
    <message>
        <source>%1 must not be empty</source>
        <translation>%1 darf nicht leer sein</translation>
    </message>
    <message>
        <source>%1 must be at most 1e9 in size, not &quot;%2&quot;</source>
        <translation>%1 darf betragsmäßig höchstens 1e9 sein, nicht „%2“</translation>
    </message>
    <message>
        <source>%1 must be a number with a decimal point, not &quot;%2&quot;</source>
        <translation>%1 muss eine Zahl mit Dezimalpunkt sein, nicht „%2“</translation>
    </message>
    <message>
        <source>the line has %1 cells, the header %2: &quot;%3&quot;</source>
        <translation>die Zeile hat %1 Zellen, die Kopfzeile %2: „%3“</translation>
    </message>
    <message>
        <source>the header names the column &quot;%1&quot; twice, as columns %2 and %3</source>
        <translation>die Kopfzeile nennt die Spalte „%1“ zweimal, als Spalten %2 und %3</translation>
    </message>
</context>
<context>
    <name>MeasurementSchema</name>
    <message>
        <source>the store refused &quot;%1&quot;: %2</source>
        <translation>der Speicher lehnte „%1“ ab: %2</translation>
    </message>
    <message>
        <source>the store refused the checksum of part %1: %2</source>
        <translation>der Speicher lehnte die Prüfsumme von Teil %1 ab: %2</translation>
    </message>
    <message>
        <source>the store has schema version %1, newer than this program&apos;s %2: update TolTurn</source>
        <translation>der Speicher hat Schemaversion %1, neuer als die %2 dieses Programms: aktualisieren Sie TolTurn</translation>
    </message>
</context>
<context>
    <name>MeasurementStore</name>
    <message>
        <source>cannot open the measurement store %1: %2</source>
        <translation>der Messwertspeicher %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Qt&apos;s SQLite driver is not installed (Debian: libqt6sql6-sqlite)</source>
        <translation>der SQLite-Treiber von Qt ist nicht installiert (Debian: libqt6sql6-sqlite)</translation>
    </message>
    <message>
        <source>Qt&apos;s PostgreSQL driver is not installed (Debian: libqt6sql6-psql)</source>
        <translation>der PostgreSQL-Treiber von Qt ist nicht installiert (Debian: libqt6sql6-psql)</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>der Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot start a transaction</source>
        <translation>keine Transaktion möglich</translation>
    </message>
    <message>
        <source>cannot store the part</source>
        <translation>das Teil kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>cannot store point %1</source>
        <translation>Punkt %1 kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>cannot commit the part</source>
        <translation>das Teil kann nicht festgeschrieben werden</translation>
    </message>
    <message>
        <source>cannot read part %1</source>
        <translation>Teil %1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>the store has no part %1</source>
        <translation>der Speicher hat kein Teil %1</translation>
    </message>
    <message>
        <source>cannot read the points of part %1</source>
        <translation>die Punkte von Teil %1 können nicht gelesen werden</translation>
    </message>
    <message>
        <source>part %1 has a point of unknown quantity &quot;%2&quot;</source>
        <translation>Teil %1 hat einen Punkt mit unbekannter Größe „%2“</translation>
    </message>
    <message>
        <source>cannot list the parts</source>
        <translation>die Teile können nicht aufgelistet werden</translation>
    </message>
    <message>
        <source>cannot count the parts</source>
        <translation>die Teile können nicht gezählt werden</translation>
    </message>
    <message>
        <source>cannot remove part %1</source>
        <translation>Teil %1 kann nicht entfernt werden</translation>
    </message>
    <message>
        <source>the store is not named</source>
        <translation>der Speicher ist nicht angegeben</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a PostgreSQL address of the form postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?host=SOCKET_FOLDER]</source>
        <translation>„%1“ ist keine PostgreSQL-Adresse der Form postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?host=SOCKET_FOLDER]</translation>
    </message>
    <message>
        <source>a learned model needs its machine and finite figures</source>
        <translation>ein gelerntes Modell braucht seine Maschine und endliche Kennzahlen</translation>
    </message>
    <message>
        <source>cannot keep the learned model</source>
        <translation>das gelernte Modell kann nicht behalten werden</translation>
    </message>
    <message>
        <source>cannot read the learned models</source>
        <translation>die gelernten Modelle können nicht gelesen werden</translation>
    </message>
    <message>
        <source>part %1 has a damaged drive reading: %2</source>
        <translation>Teil %1 hat beschädigte Antriebsmesswerte: %2</translation>
    </message>
</context>
<context>
    <name>MeasurementsCommand</name>
    <message>
        <source>--%1 takes a number, not &quot;%2&quot;</source>
        <translation>--%1 erwartet eine Zahl, nicht „%2“</translation>
    </message>
    <message>
        <source>a part is named by its number from 1, not &quot;%1&quot;</source>
        <translation>ein Teil wird mit seiner Nummer ab 1 angegeben, nicht „%1“</translation>
    </message>
    <message>
        <source>The measured points (feature, z_mm, diameter_mm or radial_deviation_um).</source>
        <translation>Die Messpunkte (feature, z_mm, diameter_mm oder radial_deviation_um).</translation>
    </message>
    <message>
        <source>The machine the part was cut on (default: the project&apos;s).</source>
        <translation>Die Maschine, auf der das Teil gefertigt wurde (Vorgabe: die des Projekts).</translation>
    </message>
    <message>
        <source>When it was measured, ISO 8601 (default: now).</source>
        <translation>Wann gemessen wurde, ISO 8601 (Vorgabe: jetzt).</translation>
    </message>
    <message>
        <source>Who measured it.</source>
        <translation>Wer gemessen hat.</translation>
    </message>
    <message>
        <source>How: micrometer, CMM, bore gauge, …</source>
        <translation>Wie: Bügelmessschraube, KMG, Innenmessgerät, …</translation>
    </message>
    <message>
        <source>Minutes the machine had run when it was cut.</source>
        <translation>Minuten, die die Maschine beim Fertigen lief.</translation>
    </message>
    <message>
        <source>Ambient temperature when it was cut, °C.</source>
        <translation>Umgebungstemperatur beim Fertigen, °C.</translation>
    </message>
    <message>
        <source>A note.</source>
        <translation>Eine Notiz.</translation>
    </message>
    <message>
        <source>The project the part was cut from.</source>
        <translation>Das Projekt, aus dem das Teil gefertigt wurde.</translation>
    </message>
    <message>
        <source>Store a measured part.</source>
        <translation>Ein gemessenes Teil speichern.</translation>
    </message>
    <message>
        <source>give one project file and --csv FILE.csv</source>
        <translation>geben Sie eine Projektdatei und --csv FILE.csv an</translation>
    </message>
    <message>
        <source>--at takes a time as 2026-11-24T08:30:00Z, not &quot;%1&quot;</source>
        <translation>--at erwartet eine Zeit wie 2026-11-24T08:30:00Z, nicht „%1“</translation>
    </message>
    <message numerus="yes">
        <source>stored part %1: %2, %n point(s), in %3</source>
        <translation>
            <numerusform>Teil %1 gespeichert: %2, %n Punkt, in %3</numerusform>
            <numerusform>Teil %1 gespeichert: %2, %n Punkte, in %3</numerusform>
        </translation>
    </message>
    <message>
        <source>Only the parts of this machine.</source>
        <translation>Nur die Teile dieser Maschine.</translation>
    </message>
    <message>
        <source>Only parts with this in their name, measurer or method.</source>
        <translation>Nur Teile mit diesem Text im Namen, Prüfer oder Verfahren.</translation>
    </message>
    <message>
        <source>At most N parts, newest first.</source>
        <translation>Höchstens N Teile, neueste zuerst.</translation>
    </message>
    <message>
        <source>Print the list as JSON.</source>
        <translation>Die Liste als JSON ausgeben.</translation>
    </message>
    <message>
        <source>List the stored parts, newest first.</source>
        <translation>Die gespeicherten Teile auflisten, neueste zuerst.</translation>
    </message>
    <message>
        <source>--limit takes a number from 1, not &quot;%1&quot;</source>
        <translation>--limit erwartet eine Zahl ab 1, nicht „%1“</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n Punkt</numerusform>
            <numerusform>%n Punkte</numerusform>
        </translation>
    </message>
    <message>
        <source>The part&apos;s number.</source>
        <translation>Die Nummer des Teils.</translation>
    </message>
    <message>
        <source>Remove a stored part with its points.</source>
        <translation>Ein gespeichertes Teil mit seinen Punkten entfernen.</translation>
    </message>
    <message>
        <source>give the number of one part</source>
        <translation>geben Sie die Nummer eines Teils an</translation>
    </message>
    <message>
        <source>removed part %1</source>
        <translation>Teil %1 entfernt</translation>
    </message>
    <message>
        <source>Every part of this machine.</source>
        <translation>Alle Teile dieser Maschine.</translation>
    </message>
    <message>
        <source>The CSV file to write (&apos;-&apos;, the default: standard output).</source>
        <translation>Die zu schreibende CSV-Datei („-“, die Vorgabe: Standardausgabe).</translation>
    </message>
    <message>
        <source>Parts by number.</source>
        <translation>Teile nach Nummer.</translation>
    </message>
    <message>
        <source>Write stored parts&apos; points as CSV.</source>
        <translation>Die Punkte gespeicherter Teile als CSV schreiben.</translation>
    </message>
    <message>
        <source>give part numbers or --machine ID</source>
        <translation>geben Sie Teilenummern oder --machine ID an</translation>
    </message>
    <message>
        <source>The measurement history of the machines (an SQLite file or a shared PostgreSQL database): store a measured part with the project it was cut from, list, remove, export as CSV.</source>
        <translation>Die Messhistorie der Maschinen (eine SQLite-Datei oder eine gemeinsame PostgreSQL-Datenbank): ein gemessenes Teil mit seinem Projekt speichern, auflisten, entfernen, als CSV exportieren.</translation>
    </message>
    <message>
        <source>say add, list, remove or export, not &quot;%1&quot;</source>
        <translation>sagen Sie add, list, remove oder export, nicht „%1“</translation>
    </message>
    <message>
        <source>not a JSON object (%1)</source>
        <translation>kein JSON-Objekt (%1)</translation>
    </message>
    <message>
        <source>The spindle and feed drives&apos; readings during the finishing cut (JSON: spindle_current_A, spindle_idle_current_A, …; docs/learning.md).</source>
        <translation>Die Messwerte von Spindel- und Vorschubantrieb während des Schlichtschnitts (JSON: spindle_current_A, spindle_idle_current_A, …; docs/learning.md).</translation>
    </message>
</context>
<context>
    <name>MilledFeatureCheck</name>
    <message>
        <source>a milled feature needs an id</source>
        <translation>ein gefrästes Formelement braucht eine ID</translation>
    </message>
    <message>
        <source>z from %1 mm to %2 mm is not a range within the part, 0 to %3 mm</source>
        <translation>z von %1 mm bis %2 mm ist kein Bereich innerhalb des Teils, 0 bis %3 mm</translation>
    </message>
    <message>
        <source>spindle speed: %1 rpm is not positive</source>
        <translation>Spindeldrehzahl: %1 1/min ist nicht positiv</translation>
    </message>
    <message>
        <source>K_tc: %1 N/mm² is not positive</source>
        <translation>K_tc: %1 N/mm² ist nicht positiv</translation>
    </message>
    <message>
        <source>the cutting coefficients have no source: the verdict rests on numbers nobody can trace</source>
        <translation>die Schnittkraftkoeffizienten haben keine Quelle: die Bewertung beruht auf Zahlen, die niemand nachvollziehen kann</translation>
    </message>
    <message>
        <source>tolerance zone: %1 µm is not positive</source>
        <translation>Toleranzzone: %1 µm ist nicht positiv</translation>
    </message>
    <message>
        <source>a flatness has no datums (ISO 1101), found %1</source>
        <translation>eine Ebenheit hat keine Bezüge (ISO 1101), gefunden: %1</translation>
    </message>
    <message>
        <source>there is no datum &apos;%1&apos; in the project</source>
        <translation>im Projekt gibt es keinen Bezug „%1“</translation>
    </message>
    <message>
        <source>a %1 is one straight cut: its CL points are not used</source>
        <translation>ein Formelement vom Typ %1 ist ein einzelner gerader Schnitt: seine CL-Punkte werden nicht verwendet</translation>
    </message>
    <message>
        <source>milled feature %1 is not evaluated: it lacks %2</source>
        <translation>gefrästes Formelement %1 wird nicht ausgewertet, es fehlt: %2</translation>
    </message>
    <message>
        <source>id &apos;%1&apos; is already another milled feature&apos;s</source>
        <translation>ID &apos;%1&apos; gehört schon einem anderen gefrästen Formelement</translation>
    </message>
    <message>
        <source>id &apos;%1&apos; is already a feature of the profile</source>
        <translation>ID &apos;%1&apos; ist schon ein Formelement der Kontur</translation>
    </message>
    <message>
        <source>tool diameter: %1 mm is not positive</source>
        <translation>Werkzeugdurchmesser: %1 mm ist nicht positiv</translation>
    </message>
    <message>
        <source>flutes: %1 is not 1 to 12</source>
        <translation>Schneiden: %1 liegt nicht zwischen 1 und 12</translation>
    </message>
    <message>
        <source>helix angle: %1° is not 0 to 60°</source>
        <translation>Drallwinkel: %1° liegt nicht zwischen 0 und 60°</translation>
    </message>
    <message>
        <source>%1 is beyond ±%2 (TolTurn&apos;s bound)</source>
        <translation>%1 liegt außerhalb von ±%2 (Grenze von TolTurn)</translation>
    </message>
</context>
<context>
    <name>MilledFeatureOutput</name>
    <message>
        <source>not evaluated: it lacks %1</source>
        <translation>nicht ausgewertet, es fehlt: %1</translation>
    </message>
    <message>
        <source>not evaluated: %1</source>
        <translation>nicht ausgewertet: %1</translation>
    </message>
    <message>
        <source>located</source>
        <translation>lagebestimmt</translation>
    </message>
    <message>
        <source>floating</source>
        <translation>schwebend</translation>
    </message>
    <message>
        <source>form error %1 µm of %2 µm (%3 zone): </source>
        <translation>Formabweichung %1 µm von %2 µm (Zone: %3): </translation>
    </message>
    <message>
        <source>passes by %1 µm</source>
        <translation>besteht mit %1 µm Reserve</translation>
    </message>
    <message>
        <source>fails by %1 µm</source>
        <translation>verfehlt um %1 µm</translation>
    </message>
    <message>
        <source>; holds at a feed per tooth up to %1 mm</source>
        <translation>; hält bei einem Vorschub je Zahn bis %1 mm</translation>
    </message>
    <message>
        <source>Milled features (five-axis ball-end model, Öztürk &amp; Budak):</source>
        <translation>Gefräste Formelemente (Modell für fünfachsiges Kugelkopffräsen, Öztürk &amp; Budak):</translation>
    </message>
    <message>
        <source>z %1–%2 mm  </source>
        <translation>z %1–%2 mm  </translation>
    </message>
    <message>
        <source>the tool&apos;s modulus is not given: carbide&apos;s %1 N/mm² (MakeItFrom)</source>
        <translation>der E-Modul des Werkzeugs ist nicht angegeben: %1 N/mm² für Hartmetall (MakeItFrom)</translation>
    </message>
    <message>
        <source>; no feed up to the planned one holds</source>
        <translation>; kein Vorschub bis zum geplanten hält sie ein</translation>
    </message>
</context>
<context>
    <name>MilledFeatures</name>
    <message>
        <source>path point %1: %2</source>
        <translation>Bahnpunkt %1: %2</translation>
    </message>
    <message>
        <source>the ball-end tool</source>
        <translation>der Kugelkopffräser</translation>
    </message>
    <message>
        <source>the holder&apos;s springs k and k_θ</source>
        <translation>die Halterfedern k und k_θ</translation>
    </message>
    <message>
        <source>the cutting conditions</source>
        <translation>die Schnittbedingungen</translation>
    </message>
    <message>
        <source>the cutting coefficients</source>
        <translation>die Schnittkraftkoeffizienten</translation>
    </message>
    <message>
        <source>the tolerance</source>
        <translation>die Toleranz</translation>
    </message>
    <message>
        <source>the tool path (at least two CL points)</source>
        <translation>die Werkzeugbahn (mindestens zwei CL-Punkte)</translation>
    </message>
    <message>
        <source>the tool axis is zero</source>
        <translation>die Werkzeugachse ist ein Nullvektor</translation>
    </message>
    <message>
        <source>the surface normal is zero</source>
        <translation>die Flächennormale ist ein Nullvektor</translation>
    </message>
    <message>
        <source>the tool axis points into the surface</source>
        <translation>die Werkzeugachse zeigt in die Fläche hinein</translation>
    </message>
    <message>
        <source>the feed runs along the surface normal</source>
        <translation>der Vorschub verläuft entlang der Flächennormalen</translation>
    </message>
    <message>
        <source>milled feature %1 lacks %2</source>
        <translation>dem gefrästen Formelement %1 fehlt: %2</translation>
    </message>
    <message>
        <source>highest feed per tooth: %1 mm is not positive</source>
        <translation>größter Vorschub je Zahn: %1 mm ist nicht positiv</translation>
    </message>
    <message>
        <source>a tool path has 2 to %1 CL points, this one %2</source>
        <translation>eine Werkzeugbahn hat 2 bis %1 CL-Punkte, diese %2</translation>
    </message>
    <message>
        <source>the ball is where it was at the point before</source>
        <translation>die Kugel steht dort, wo sie am vorigen Punkt stand</translation>
    </message>
    <message>
        <source>the predicted deflection is not finite: the tool&apos;s data lie beyond what the model computes</source>
        <translation>die vorhergesagte Durchbiegung ist nicht endlich: die Daten des Werkzeugs liegen jenseits dessen, was das Modell berechnet</translation>
    </message>
</context>
<context>
    <name>MillingCommand</name>
    <message>
        <source>Öztürk &amp; Budak&apos;s cut 1–4 (001 table 4): tool, cut and speed; the options below change it.</source>
        <translation>Schnitt 1–4 von Öztürk &amp; Budak (001 Tabelle 4): Werkzeug, Schnitt und Drehzahl; die Optionen unten ändern ihn.</translation>
    </message>
    <message>
        <source>Ball diameter in mm.</source>
        <translation>Kugeldurchmesser in mm.</translation>
    </message>
    <message>
        <source>Number of flutes.</source>
        <translation>Anzahl der Schneiden.</translation>
    </message>
    <message>
        <source>Helix angle in degrees (default 30).</source>
        <translation>Drallwinkel in Grad (Vorgabe 30).</translation>
    </message>
    <message>
        <source>Lead angle in degrees (default 0).</source>
        <translation>Anstellwinkel (Lead) in Grad (Vorgabe 0).</translation>
    </message>
    <message>
        <source>Tilt angle in degrees (default 0).</source>
        <translation>Kippwinkel (Tilt) in Grad (Vorgabe 0).</translation>
    </message>
    <message>
        <source>Axial depth of cut along the surface normal in mm.</source>
        <translation>Axiale Schnitttiefe entlang der Flächennormalen in mm.</translation>
    </message>
    <message>
        <source>Side cut into uncut material this wide, in mm (table 1); without it or --step-over, a slot.</source>
        <translation>Seitlicher Schnitt in unbearbeitetes Material dieser Breite, in mm (Tabelle 1); ohne diese Option oder --step-over eine Nut.</translation>
    </message>
    <message>
        <source>Cut beside a previous pass this far away, in mm (table 2).</source>
        <translation>Schnitt neben einer vorherigen Bahn in diesem Abstand, in mm (Tabelle 2).</translation>
    </message>
    <message>
        <source>Up milling (default down milling).</source>
        <translation>Gegenlauffräsen (Vorgabe Gleichlauffräsen).</translation>
    </message>
    <message>
        <source>Feed per tooth in mm.</source>
        <translation>Vorschub je Zahn in mm.</translation>
    </message>
    <message>
        <source>Spindle speed in 1/min.</source>
        <translation>Spindeldrehzahl in 1/min.</translation>
    </message>
    <message>
        <source>The tool and material&apos;s cutting and edge coefficients Ktc,Krc,Kac (N/mm²),Kte,Kre,Kae (N/mm) of the linear edge-force model (001 eq. 11). Required: 001 prints none, and TolTurn&apos;s data library has none for ball-end milling.</source>
        <translation>Die Schnitt- und Kantenkoeffizienten Ktc,Krc,Kac (N/mm²),Kte,Kre,Kae (N/mm) von Werkzeug und Werkstoff im linearen Kantenkraftmodell (001 Gl. 11). Erforderlich: 001 druckt keine, und TolTurns Datenbibliothek hat keine für das Kugelkopffräsen.</translation>
    </message>
    <message>
        <source>Disc elements over the engaged height (default 200).</source>
        <translation>Scheibenelemente über die eingreifende Höhe (Vorgabe 200).</translation>
    </message>
    <message>
        <source>Rotation angles per revolution (default 360).</source>
        <translation>Drehwinkel je Umdrehung (Vorgabe 360).</translation>
    </message>
    <message>
        <source>Print the results as JSON.</source>
        <translation>Die Ergebnisse als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Print every rotation angle as CSV.</source>
        <translation>Jeden Drehwinkel als CSV ausgeben.</translation>
    </message>
    <message>
        <source>give --radial-depth or --step-over, not both</source>
        <translation>--radial-depth oder --step-over angeben, nicht beides</translation>
    </message>
    <message>
        <source>give --case N, or the tool and cut: %1 missing</source>
        <translation>--case N oder Werkzeug und Schnitt angeben: %1 fehlt</translation>
    </message>
    <message>
        <source>--coefficients Ktc,Krc,Kac,Kte,Kre,Kae is required: Öztürk &amp; Budak print no coefficients (theirs come from an orthogonal-cutting database of Ti6Al4V through the oblique transformation), and TolTurn&apos;s data library has none for ball-end milling; give your tool and material&apos;s (docs/milling.md)</source>
        <translation>--coefficients Ktc,Krc,Kac,Kte,Kre,Kae ist erforderlich: Öztürk &amp; Budak drucken keine Koeffizienten (ihre stammen aus einer Orthogonalschnitt-Datenbank für Ti6Al4V über die Schrägschnitt-Transformation), und TolTurns Datenbibliothek hat keine für das Kugelkopffräsen; geben Sie die Ihres Werkzeugs und Werkstoffs an (docs/milling.md)</translation>
    </message>
    <message>
        <source>--coefficients: &quot;%1&quot; is not six numbers Ktc,Krc,Kac,Kte,Kre,Kae of at most %2</source>
        <translation>--coefficients: „%1“ sind nicht sechs Zahlen Ktc,Krc,Kac,Kte,Kre,Kae von höchstens %2</translation>
    </message>
    <message>
        <source>slot</source>
        <translation>Nut</translation>
    </message>
    <message>
        <source>side cut %1 mm wide</source>
        <translation>seitlicher Schnitt %1 mm breit</translation>
    </message>
    <message>
        <source>step-over %1 mm</source>
        <translation>Bahnabstand %1 mm</translation>
    </message>
    <message>
        <source>Öztürk &amp; Budak (001) table 4, case %1: DMU 50 Evolution, Ti6Al4V</source>
        <translation>Öztürk &amp; Budak (001) Tabelle 4, Fall %1: DMU 50 Evolution, Ti6Al4V</translation>
    </message>
    <message>
        <source>Ball-end mill Ø%1 mm, %2 flutes, helix %3°; %4, %5 milling, axial depth %6 mm, feed %7 mm/tooth, %8 1/min; lead %9°, tilt %10°</source>
        <translation>Kugelkopffräser Ø%1 mm, %2 Schneiden, Drall %3°; %4, %5, axiale Zustellung %6 mm, Vorschub %7 mm/Zahn, %8 1/min; Anstellwinkel %9°, Kippwinkel %10°</translation>
    </message>
    <message>
        <source>down</source>
        <translation>Gleichlauffräsen</translation>
    </message>
    <message>
        <source>up</source>
        <translation>Gegenlauffräsen</translation>
    </message>
    <message>
        <source>Coefficients (given): Ktc %1, Krc %2, Kac %3 N/mm²; Kte %4, Kre %5, Kae %6 N/mm</source>
        <translation>Koeffizienten (angegeben): Ktc %1, Krc %2, Kac %3 N/mm²; Kte %4, Kre %5, Kae %6 N/mm</translation>
    </message>
    <message>
        <source>%1 disc elements, %2 rotation angles per revolution</source>
        <translation>%1 Scheibenelemente, %2 Drehwinkel je Umdrehung</translation>
    </message>
    <message>
        <source>Peak forces on the tool: F %1 N, C %2 N, N %3 N (feed, cross-feed, surface normal); resultant %4 N</source>
        <translation>Spitzenkräfte am Werkzeug: F %1 N, C %2 N, N %3 N (Vorschub, quer dazu, Flächennormale); Resultierende %4 N</translation>
    </message>
    <message>
        <source>Torque: mean %1 N·m, peak %2 N·m; mean spindle power %3 W</source>
        <translation>Drehmoment: Mittel %1 N·m, Spitze %2 N·m; mittlere Spindelleistung %3 W</translation>
    </message>
    <message>
        <source>From where the holder grips the tool to its tip, in mm.</source>
        <translation>Von der Einspannung im Halter bis zur Werkzeugspitze, in mm.</translation>
    </message>
    <message>
        <source>Diameter of the cylinder that stands for the fluted tool in bending, in mm.</source>
        <translation>Durchmesser des Zylinders, der das genutete Werkzeug bei Biegung ersetzt, in mm.</translation>
    </message>
    <message>
        <source>Young&apos;s modulus of the tool in N/mm² (default 630000, tungsten carbide; cemented carbides span 530000–700000).</source>
        <translation>Elastizitätsmodul des Werkzeugs in N/mm² (Vorgabe 630000, Wolframkarbid; Hartmetalle reichen von 530000 bis 700000).</translation>
    </message>
    <message>
        <source>The holder&apos;s springs k (N/mm) and k_θ (N·mm/rad) as K,KTHETA; with --case, 001&apos;s calibration 6306,1.656e7 for its tool.</source>
        <translation>Die Federn des Halters k (N/mm) und k_θ (N·mm/rad) als K,KTHETA; mit --case die Kalibrierung aus 001, 6306,1.656e7, für dessen Werkzeug.</translation>
    </message>
    <message>
        <source>the tool&apos;s structure is needed: %1 missing</source>
        <translation>der Aufbau des Werkzeugs wird benötigt: %1 fehlt</translation>
    </message>
    <message>
        <source>--holder: &quot;%1&quot; is not two numbers K,KTHETA</source>
        <translation>--holder: „%1“ sind nicht zwei Zahlen K,KTHETA</translation>
    </message>
    <message>
        <source>The surface&apos;s flatness or profile tolerance t in mm.</source>
        <translation>Ebenheits- oder Profiltoleranz t der Fläche in mm.</translation>
    </message>
    <message>
        <source>A profile tolerance with datums: every normal error within ±t/2 (default: a floating zone, the spread within t).</source>
        <translation>Eine Profiltoleranz mit Bezügen: jede Normalabweichung innerhalb ±t/2 (Vorgabe: eine schwebende Zone, die Spanne innerhalb t).</translation>
    </message>
    <message>
        <source>The largest feed per tooth the tool&apos;s maker allows, in mm.</source>
        <translation>Der größte Vorschub je Zahn, den der Werkzeughersteller zulässt, in mm.</translation>
    </message>
    <message>
        <source>Leads to search, LO,HI in degrees (default -40,40).</source>
        <translation>Zu durchsuchende Anstellwinkel, LO,HI in Grad (Vorgabe -40,40).</translation>
    </message>
    <message>
        <source>Tilts to search, LO,HI in degrees (default -40,40).</source>
        <translation>Zu durchsuchende Kippwinkel, LO,HI in Grad (Vorgabe -40,40).</translation>
    </message>
    <message>
        <source>Leads and tilts of the window, each (default 64).</source>
        <translation>Anstell- und Kippwinkel des Fensters, je (Vorgabe 64).</translation>
    </message>
    <message>
        <source>Threads (default 2).</source>
        <translation>Threads (Vorgabe 2).</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not LO,HI in degrees with -60 &lt;= LO &lt; HI &lt;= 60</source>
        <translation>--%1: „%2“ ist nicht LO,HI in Grad mit -60 &lt;= LO &lt; HI &lt;= 60</translation>
    </message>
    <message>
        <source>--max-feed-per-tooth is required: the largest feed per tooth the tool&apos;s maker allows (TolTurn&apos;s data library has no ball-end mills)</source>
        <translation>--max-feed-per-tooth ist erforderlich: der größte Vorschub je Zahn, den der Werkzeughersteller zulässt (TolTurns Datenbibliothek hat keine Kugelkopffräser)</translation>
    </message>
    <message>
        <source>Tolerance %1 µm, %2; feed per tooth up to %3 mm</source>
        <translation>Toleranz %1 µm, %2; Vorschub je Zahn bis %3 mm</translation>
    </message>
    <message>
        <source>floating zone (flatness, or profile without datums): spread of the normal error</source>
        <translation>schwebende Zone (Ebenheit oder Profil ohne Bezüge): Spanne der Normalabweichung</translation>
    </message>
    <message>
        <source>located zone (profile with datums): normal error within ±t/2</source>
        <translation>lagebestimmte Zone (Profil mit Bezügen): Normalabweichung innerhalb ±t/2</translation>
    </message>
    <message>
        <source>Window %1 × %2: %3 cells with the cut on the ball, %4 of them hold the tolerance</source>
        <translation>Fenster %1 × %2: %3 Zellen mit dem Schnitt auf der Kugel, %4 davon halten die Toleranz</translation>
    </message>
    <message>
        <source>No lead and tilt in the bounds holds the tolerance at any feed: the edge forces alone deflect the tool too far, or the cut does not stay on the ball.</source>
        <translation>Kein Anstell- und Kippwinkel in den Grenzen hält die Toleranz bei irgendeinem Vorschub: schon die Kantenkräfte biegen das Werkzeug zu weit aus, oder der Schnitt bleibt nicht auf der Kugel.</translation>
    </message>
    <message>
        <source>Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min); form error %5 µm (%6 NLopt Subplex evaluations after the window)</source>
        <translation>Plan: Anstellwinkel %1°, Kippwinkel %2°, Vorschub %3 mm/Zahn (%4 mm/min); Formabweichung %5 µm (%6 Auswertungen mit NLopt Subplex nach dem Fenster)</translation>
    </message>
    <message>
        <source>Five-axis ball-end milling forces over a revolution (Öztürk &amp; Budak): on the tool in feed, cross-feed and normal directions, torque and spindle power.</source>
        <translation>Kräfte beim fünfachsigen Kugelkopffräsen über eine Umdrehung (Öztürk &amp; Budak): am Werkzeug in Vorschub-, Quer- und Normalenrichtung, Drehmoment und Spindelleistung.</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>--json oder --csv angeben, nicht beides</translation>
    </message>
    <message>
        <source>The ball-end mill&apos;s deflection over a revolution and the surface error along the normal it leaves (Öztürk &amp; Budak table 3): the tool a cantilever on springs k, k_θ.</source>
        <translation>Die Ausbiegung des Kugelkopffräsers über eine Umdrehung und die Flächenabweichung entlang der Normalen, die sie hinterlässt (Öztürk &amp; Budak Tabelle 3): das Werkzeug ein Kragbalken auf den Federn k, k_θ.</translation>
    </message>
    <message>
        <source>Tool: overhang %1 mm, a Ø%2 mm cylinder of E = %3 N/mm², holder k = %4 N/mm, k_θ = %5 N·mm/rad%6</source>
        <translation>Werkzeug: Auskraglänge %1 mm, ein Zylinder Ø%2 mm mit E = %3 N/mm², Halter k = %4 N/mm, k_θ = %5 N·mm/rad%6</translation>
    </message>
    <message>
        <source> (001&apos;s calibration for its tool)</source>
        <translation> (Kalibrierung aus 001 für dessen Werkzeug)</translation>
    </message>
    <message>
        <source>Surface error along the normal, over a revolution: %1 to %2 µm (positive: material left); generating point %3 mm up the axis. Only the tool deflects in this model.</source>
        <translation>Flächenabweichung entlang der Normalen über eine Umdrehung: %1 bis %2 µm (positiv: Material bleibt stehen); erzeugender Punkt %3 mm die Achse hinauf. In diesem Modell biegt sich nur das Werkzeug.</translation>
    </message>
    <message>
        <source>The lead, tilt and feed per tooth of least machining time that keep the ball-end surface within its flatness or profile tolerance, with the lead–tilt window.</source>
        <translation>Anstellwinkel, Kippwinkel und Vorschub je Zahn mit der kürzesten Bearbeitungszeit, die die kugelkopfgefräste Fläche in ihrer Ebenheits- oder Profiltoleranz halten, mit dem Anstell-Kipp-Fenster.</translation>
    </message>
    <message>
        <source>--tolerance is required: the surface&apos;s tolerance t in mm</source>
        <translation>--tolerance ist erforderlich: die Toleranz t der Fläche in mm</translation>
    </message>
    <message>
        <source>takes a project file only with --feature ID: &quot;%1&quot;</source>
        <translation>nimmt eine Projektdatei nur mit --feature ID an: „%1“</translation>
    </message>
    <message>
        <source>--feature needs the project file PROJECT it is in</source>
        <translation>--feature benötigt die Projektdatei PROJECT, in der das Formelement steht</translation>
    </message>
    <message>
        <source>With --feature: write the plan (lead, tilt, feed per tooth) into the feature&apos;s conditions in PROJECT.</source>
        <translation>Mit --feature: den Plan (Anstellwinkel, Kippwinkel, Vorschub je Zahn) in die Schnittbedingungen des Formelements in PROJECT schreiben.</translation>
    </message>
    <message>
        <source>--tolerance, --located: the tolerance comes from the project&apos;s feature; change it there</source>
        <translation>--tolerance, --located: die Toleranz stammt aus dem Formelement des Projekts; ändern Sie sie dort</translation>
    </message>
    <message>
        <source>--save: no plan holds the tolerance; %1 is left as it was</source>
        <translation>--save: kein Plan hält die Toleranz; %1 bleibt unverändert</translation>
    </message>
    <message>
        <source>No feed holds the tolerance along the path: the edge forces alone deflect the tool too far at its tool axes.</source>
        <translation>Kein Vorschub hält die Toleranz entlang der Bahn: schon die Kantenkräfte biegen das Werkzeug bei den Werkzeugachsen der Bahn zu weit aus.</translation>
    </message>
    <message>
        <source>Plan along the path&apos;s own tool axes: feed %1 mm/tooth (%2 mm/min); form error %3 µm</source>
        <translation>Plan mit den eigenen Werkzeugachsen der Bahn: Vorschub %1 mm/Zahn (%2 mm/min); Formabweichung %3 µm</translation>
    </message>
    <message>
        <source>--save needs PROJECT --feature ID</source>
        <translation>--save benötigt PROJECT --feature ID</translation>
    </message>
    <message>
        <source>%1: the tool and cut come from the project&apos;s feature; change them there</source>
        <translation>%1: Werkzeug und Schnitt stammen aus dem Formelement des Projekts; ändern Sie sie dort</translation>
    </message>
    <message>
        <source>--feature: there is no milled feature &quot;%1&quot; in %2</source>
        <translation>--feature: in %2 gibt es kein gefrästes Formelement „%1“</translation>
    </message>
    <message>
        <source>milled feature %1 lacks %2</source>
        <translation>dem gefrästen Formelement %1 fehlt: %2</translation>
    </message>
    <message>
        <source>--%1: the tool&apos;s structure comes from the project&apos;s feature; change it there</source>
        <translation>--%1: der Aufbau des Werkzeugs stammt aus dem Formelement des Projekts; ändern Sie ihn dort</translation>
    </message>
    <message>
        <source>The milled feature of the project PROJECT to compute, with its tool, cut, coefficients and tolerance.</source>
        <translation>Das zu berechnende gefräste Formelement des Projekts PROJECT, mit seinem Werkzeug, Schnitt, seinen Koeffizienten und seiner Toleranz.</translation>
    </message>
    <message>
        <source>With --feature, a patch&apos;s CL point to compute at (default 1; mill-optimize plans the whole path).</source>
        <translation>Mit --feature der CL-Punkt einer Freiformfläche, an dem gerechnet wird (Vorgabe 1; mill-optimize plant die ganze Bahn).</translation>
    </message>
    <message>
        <source>The plan is saved in %1, feature %2 (the feed per tooth rounded down to 0.0001 mm).</source>
        <translation>Der Plan ist in %1 gespeichert, Formelement %2 (Vorschub je Zahn auf 0,0001 mm abgerundet).</translation>
    </message>
    <message>
        <source>--save plans at evaluate&apos;s resolution (200 slices, 360 angles): leave out --slices and --angles</source>
        <translation>--save plant mit der Auflösung von evaluate (200 Scheiben, 360 Winkel): --slices und --angles weglassen</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
</context>
<context>
    <name>MillingReport</name>
    <message>
        <source>Ø%1 mm, 1 flute, helix %2°</source>
        <translation>Ø%1 mm, 1 Schneide, Drall %2°</translation>
    </message>
    <message>
        <source>Ø%1 mm, %2 flutes, helix %3°</source>
        <translation>Ø%1 mm, %2 Schneiden, Drall %3°</translation>
    </message>
    <message>
        <source>down milling</source>
        <translation>Gleichlauffräsen</translation>
    </message>
    <message>
        <source>up milling</source>
        <translation>Gegenlauffräsen</translation>
    </message>
    <message>
        <source>, s %1 mm</source>
        <translation>, s %1 mm</translation>
    </message>
    <message>
        <source>; f_z %1 mm; %2 rpm; </source>
        <translation>; f_z %1 mm; %2 1/min; </translation>
    </message>
    <message>
        <source>lead and tilt from the path</source>
        <translation>Anstell- und Kippwinkel aus der Bahn</translation>
    </message>
    <message>
        <source>lead %1°, tilt %2°</source>
        <translation>Anstellwinkel %1°, Kippwinkel %2°</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>flatness</source>
        <translation>Ebenheit</translation>
    </message>
    <message>
        <source>located, datums %1</source>
        <translation>lagebestimmt, Bezüge %1</translation>
    </message>
    <message>
        <source>floating</source>
        <translation>schwebend</translation>
    </message>
    <message>
        <source>%1 %2 µm, %3</source>
        <translation>%1 %2 µm, %3</translation>
    </message>
    <message>
        <source>not evaluated: lacks %1</source>
        <translation>nicht ausgewertet, es fehlt: %1</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>abgelehnt: %1</translation>
    </message>
    <message>
        <source>passes by %1 µm</source>
        <translation>besteht mit %1 µm Reserve</translation>
    </message>
    <message>
        <source>largest f_z that holds: %1 mm</source>
        <translation>größtes f_z, das die Toleranz hält: %1 mm</translation>
    </message>
    <message>
        <source>no f_z up to the planned one holds</source>
        <translation>kein f_z bis zum geplanten hält die Toleranz</translation>
    </message>
    <message>
        <source>fails by %1 µm; %2</source>
        <translation>verfehlt um %1 µm; %2</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Conditions</source>
        <translation>Schnittwerte</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Form error [µm]</source>
        <translation>Formabweichung [µm]</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>E of the tool not given: carbide&apos;s %1 N/mm² (MakeItFrom)</source>
        <translation>E des Werkzeugs nicht angegeben: %1 N/mm² für Hartmetall (MakeItFrom)</translation>
    </message>
    <message>
        <source>coefficients without a source</source>
        <translation>Koeffizienten ohne Quelle</translation>
    </message>
    <message>
        <source>coefficients: %1</source>
        <translation>Koeffizienten: %1</translation>
    </message>
    <message>
        <source>δ_N, least</source>
        <translation>δ_N, kleinstes</translation>
    </message>
    <message>
        <source>δ_N, greatest</source>
        <translation>δ_N, größtes</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>Zone, unten</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>Zone, oben</translation>
    </message>
    <message>
        <source>arc length along the path [mm]</source>
        <translation>Bogenlänge entlang der Bahn [mm]</translation>
    </message>
    <message>
        <source>surface-normal error δ_N [µm]</source>
        <translation>Abweichung entlang der Flächennormalen δ_N [µm]</translation>
    </message>
    <message>
        <source>%1: surface-normal error along the path (%2 zone)</source>
        <translation>%1: Abweichung entlang der Flächennormalen im Verlauf der Bahn (Zone: %2)</translation>
    </message>
    <message>
        <source>located</source>
        <translation>lagebestimmt</translation>
    </message>
    <message>
        <source>%1: largest force on the tool %2 N, mean torque %3 N·m, spindle power %4 W.</source>
        <translation>%1: größte Kraft am Werkzeug %2 N, mittleres Drehmoment %3 N·m, Spindelleistung %4 W.</translation>
    </message>
    <message>
        <source>Each milled feature is evaluated with Öztürk &amp; Budak&apos;s ball-end model [9]: the forces bend the tool and leave the surface-normal error δ_N (its range over a revolution at each point of the path). The form error is the spread of δ_N along the path for a floating zone, twice its largest magnitude for a located one (ISO 1101 [6]).</source>
        <translation>Jedes gefräste Formelement wird mit dem Kugelkopfmodell von Öztürk &amp; Budak [9] ausgewertet: Die Kräfte biegen das Werkzeug aus und hinterlassen die Abweichung entlang der Flächennormalen δ_N (ihre Spanne über eine Umdrehung an jedem Punkt der Bahn). Die Formabweichung ist bei einer schwebenden Zone die Spanne von δ_N entlang der Bahn, bei einer lagebestimmten Zone das Doppelte ihres größten Betrags (ISO 1101 [6]).</translation>
    </message>
</context>
<context>
    <name>ModelFiles</name>
    <message>
        <source>model form</source>
        <translation>Modellform</translation>
    </message>
    <message>
        <source>a coefficient must be a number, not %1</source>
        <translation>ein Koeffizient muss eine Zahl sein, nicht %1</translation>
    </message>
    <message numerus="yes">
        <source>a %1 model does not take %n coefficient(s)</source>
        <translation>
            <numerusform>ein %1-Modell nimmt nicht %n Koeffizienten</numerusform>
            <numerusform>ein %1-Modell nimmt nicht %n Koeffizienten</numerusform>
        </translation>
    </message>
    <message>
        <source>file format</source>
        <translation>Dateiformat</translation>
    </message>
    <message>
        <source>version %1 is not one this TolTurn reads (1)</source>
        <translation>Version %1 kann dieses TolTurn nicht lesen (1)</translation>
    </message>
    <message>
        <source>cannot be read: %1</source>
        <translation>kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>not a valid JSON object: %1</source>
        <translation>kein gültiges JSON-Objekt: %1</translation>
    </message>
</context>
<context>
    <name>Names</name>
    <message>
        <source>chuck</source>
        <translation>Futter</translation>
    </message>
    <message>
        <source>between centres</source>
        <translation>zwischen Spitzen</translation>
    </message>
    <message>
        <source>chuck + tailstock</source>
        <translation>Futter + Reitstock</translation>
    </message>
    <message>
        <source>cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <source>face</source>
        <translation>Planfläche</translation>
    </message>
    <message>
        <source>cone</source>
        <translation>Kegel</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>Fase</translation>
    </message>
    <message>
        <source>radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>flatness</source>
        <translation>Ebenheit</translation>
    </message>
    <message>
        <source>cylindricity</source>
        <translation>Zylinderform</translation>
    </message>
    <message>
        <source>profile of a surface</source>
        <translation>Flächenform</translation>
    </message>
    <message>
        <source>parallelism</source>
        <translation>Parallelität</translation>
    </message>
    <message>
        <source>perpendicularity</source>
        <translation>Rechtwinkligkeit</translation>
    </message>
    <message>
        <source>coaxiality</source>
        <translation>Koaxialität</translation>
    </message>
    <message>
        <source>circular radial run-out</source>
        <translation>Rundlauf</translation>
    </message>
    <message>
        <source>circular axial run-out</source>
        <translation>Planlauf</translation>
    </message>
    <message>
        <source>total radial run-out</source>
        <translation>Gesamtrundlauf</translation>
    </message>
    <message>
        <source>total axial run-out</source>
        <translation>Gesamtplanlauf</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>collet</source>
        <translation>Spannzange</translation>
    </message>
    <message>
        <source>flat</source>
        <translation>Abflachung</translation>
    </message>
    <message>
        <source>keyway</source>
        <translation>Passfedernut</translation>
    </message>
    <message>
        <source>surface patch</source>
        <translation>Freiformfläche</translation>
    </message>
    <message>
        <source>slot</source>
        <translation>Nut</translation>
    </message>
    <message>
        <source>side cut</source>
        <translation>seitlicher Schnitt</translation>
    </message>
    <message>
        <source>step-over</source>
        <translation>Bahnabstand</translation>
    </message>
</context>
<context>
    <name>Operations</name>
    <message>
        <source>another set-up</source>
        <translation>einer anderen Aufspannung</translation>
    </message>
    <message>
        <source>datum %1 on %2 is cut in %3</source>
        <translation>Bezug %1 auf %2 wird in %3 bearbeitet</translation>
    </message>
    <message>
        <source>%1 is cut in %2</source>
        <translation>%1 wird in %2 bearbeitet</translation>
    </message>
    <message>
        <source>spans set-ups: %1, %2 in %3; clamping again adds 0–%4 µm (%5)</source>
        <translation>erstreckt sich über mehrere Aufspannungen: %1, %2 in %3; das Umspannen fügt 0–%4 µm hinzu (%5)</translation>
    </message>
    <message>
        <source>; it holds with the largest of it</source>
        <translation>; sie wird auch mit dem größten Wert eingehalten</translation>
    </message>
    <message>
        <source>; it holds only if the re-clamping error stays below %1 µm</source>
        <translation>; sie wird nur eingehalten, wenn der Umspannfehler unter %1 µm bleibt</translation>
    </message>
    <message>
        <source>; it fails even without it</source>
        <translation>; sie wird selbst ohne ihn nicht eingehalten</translation>
    </message>
    <message>
        <source>feature %1 lies in the jaws of %2 (%3 mm from its held end): no tool reaches it there; name it in an operation that holds the other end</source>
        <translation>Formelement %1 liegt in den Spannbacken von %2 (%3 mm vom gespannten Ende): dort erreicht es kein Werkzeug; führen Sie es in einer Aufspannung auf, die das andere Ende spannt</translation>
    </message>
    <message>
        <source>an operation needs a name</source>
        <translation>eine Aufspannung braucht einen Namen</translation>
    </message>
    <message>
        <source>two operations are named &quot;%1&quot;</source>
        <translation>zwei Aufspannungen heißen &quot;%1&quot;</translation>
    </message>
    <message>
        <source>operation &quot;%1&quot; cuts no feature</source>
        <translation>Aufspannung &quot;%1&quot; bearbeitet kein Formelement</translation>
    </message>
    <message>
        <source>there is no feature &quot;%1&quot;</source>
        <translation>es gibt kein Formelement &quot;%1&quot;</translation>
    </message>
    <message>
        <source>feature %1 is named by two operations</source>
        <translation>Formelement %1 ist in zwei Aufspannungen aufgeführt</translation>
    </message>
    <message>
        <source>the part is not held in a chuck in one set-up</source>
        <translation>das Teil wird nicht in einer Aufspannung im Spannfutter gehalten</translation>
    </message>
    <message>
        <source>no feature lies in the jaws</source>
        <translation>kein Formelement liegt in den Spannbacken</translation>
    </message>
    <message>
        <source>there is no outer cylinder to hold the part by at its other end</source>
        <translation>es gibt keinen Außenzylinder, an dem das Teil am anderen Ende gespannt werden kann</translation>
    </message>
    <message>
        <source>the jaws of %2 (%3 mm) cover %1: turn the part end for end and hold it %4 mm on %5 Ø%6, finished in %2, to turn them in %7</source>
        <translation>die Spannbacken von %2 (%3 mm) decken %1 ab: das Teil umdrehen und %4 mm an %5 Ø%6, fertig in %2, spannen, um sie in %7 zu drehen</translation>
    </message>
    <message>
        <source>%1 cuts no feature: the later operations name them all</source>
        <translation>%1 bearbeitet kein Formelement: die späteren Aufspannungen nennen sie alle</translation>
    </message>
    <message>
        <source>feature %1 is in the bore that opens at the end %2 holds: no tool reaches it there; name it in an operation that holds the other end</source>
        <translation>Formelement %1 liegt in der Bohrung, die sich an dem Ende öffnet, das %2 spannt: dort erreicht es kein Werkzeug; führen Sie es in einer Aufspannung auf, die das andere Ende spannt</translation>
    </message>
    <message>
        <source>, a chuck&apos;s figure: no collet maker&apos;s is in the data</source>
        <translation>, ein Wert für Futter: kein Wert eines Spannzangenherstellers ist in den Daten</translation>
    </message>
</context>
<context>
    <name>Optimiser</name>
    <message>
        <source>The search stopped at its time limit of %1 s after %2 plans: the plan shown is the best found by then, not necessarily the optimum.</source>
        <translation>Die Suche endete an ihrer Zeitgrenze von %1 s nach %2 Plänen: der gezeigte Plan ist der bis dahin beste, nicht unbedingt das Optimum.</translation>
    </message>
    <message>
        <source>On the section its own finishing depth (%1 mm) leaves, the plan the search found violated %2 %3; the speeds and feeds were searched again at depth %4 mm.</source>
        <translation>Auf dem Querschnitt, den seine eigene Schlichttiefe (%1 mm) lässt, verletzte der gefundene Plan %2 %3; Schnittgeschwindigkeit und Vorschub wurden bei der Tiefe %4 mm erneut gesucht.</translation>
    </message>
    <message>
        <source>Stated on the steps a program gives them (%1 m/min, %2 mm/rev, %3 mm), the plan breaks a constraint: it is kept at full precision, and the program rounds it.</source>
        <translation>Auf die Schritte gebracht, in denen ein Programm sie angibt (%1 m/min, %2 mm/U, %3 mm), verletzt der Plan eine Bedingung: Er bleibt in voller Genauigkeit, und das Programm rundet ihn.</translation>
    </message>
    <message>
        <source>The range %1–%2 %5 holds no value on the step a program states (%3 %5): the plan keeps %4 %5, which the program rounds.</source>
        <translation>Der Bereich %1–%2 %5 enthält keinen Wert auf dem Schritt, in dem ein Programm ihn angibt (%3 %5): Der Plan behält %4 %5, und das Programm rundet es.</translation>
    </message>
</context>
<context>
    <name>Planning</name>
    <message>
        <source>tolerance %1</source>
        <translation>Toleranz %1</translation>
    </message>
    <message>
        <source>the optimiser needs the insert&apos;s ranges of cutting speed, feed and depth of cut (from its maker&apos;s catalogue), with their source</source>
        <translation>die Optimierung benötigt die Bereiche von Schnittgeschwindigkeit, Vorschub und Schnitttiefe der Wendeschneidplatte (aus dem Herstellerkatalog) mit ihrer Quelle</translation>
    </message>
    <message>
        <source>No Taylor constants in the project&apos;s planning data: tool life and tool cost are not in the objective, and there is no tool-life constraint.</source>
        <translation>Keine Taylor-Konstanten in den Planungsdaten des Projekts: Standzeit und Werkzeugkosten gehen nicht in die Zielfunktion ein, und es gibt keine Standzeit-Randbedingung.</translation>
    </message>
    <message>
        <source>No spindle torque limit given (planning.max_torque_Nm): torque is not constrained.</source>
        <translation>Keine Drehmomentgrenze der Spindel angegeben (planning.max_torque_Nm): das Drehmoment ist nicht begrenzt.</translation>
    </message>
    <message>
        <source>No spindle power limit known (machine data or planning.max_power_kW): power is not constrained.</source>
        <translation>Keine Grenze der Spindelleistung bekannt (Maschinendaten oder planning.max_power_kW): die Leistung ist nicht begrenzt.</translation>
    </message>
    <message>
        <source>No spindle speed limit known (machine data or planning.max_spindle_speed_rpm): spindle speed is not constrained.</source>
        <translation>Keine Drehzahlgrenze bekannt (Maschinendaten oder planning.max_spindle_speed_rpm): die Drehzahl ist nicht begrenzt.</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius: at least %2 roughing passes at the insert&apos;s largest depth of cut (%3 mm), and the optimiser plans up to %4; turn from a smaller bar</source>
        <translation>das Rohteil lässt %1 mm auf dem Radius abzutragen: mindestens %2 Schruppschnitte bei der größten Schnitttiefe der Wendeschneidplatte (%3 mm), und der Optimierer plant bis zu %4; drehen Sie aus einer kleineren Stange</translation>
    </message>
    <message>
        <source>The tolerance constraints include what was learned of the machine from its measured parts (%1); parts not learned from were predicted to %2 µm RMS.</source>
        <translation>Die Toleranz-Randbedingungen enthalten, was von der Maschine aus ihren gemessenen Teilen gelernt wurde (%1); nicht gelernte Teile wurden auf %2 µm RMS vorhergesagt.</translation>
    </message>
    <message>
        <source>least cost needs the machine and operator rate per minute, but it is %1</source>
        <translation>minimale Kosten brauchen den Maschinen- und Bedienerstundensatz je Minute, er ist aber %1</translation>
    </message>
    <message>
        <source>with a predicted value that is not finite</source>
        <translation>mit einem vorhergesagten Wert, der nicht endlich ist</translation>
    </message>
    <message>
        <source>by %1 %</source>
        <translation>um %1 %</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius of the outer profile, less than the insert&apos;s smallest depth of cut (%2 mm, planning.ranges.depth_of_cut_mm): no pass can take it</source>
        <translation>das Rohteil lässt am Radius der Außenkontur %1 mm abzutragen, weniger als die kleinste Schnitttiefe der Wendeschneidplatte (%2 mm, planning.ranges.depth_of_cut_mm): kein Schnitt kann das abnehmen</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius, between what %2 and %3 passes at depths of cut from %4 to %5 mm (planning.ranges.depth_of_cut_mm) can take: at most %6 mm, at least %7 mm</source>
        <translation>das Rohteil lässt am Radius %1 mm abzutragen, zwischen dem, was %2 und %3 Schnitte mit Schnitttiefen von %4 bis %5 mm (planning.ranges.depth_of_cut_mm) abnehmen können: höchstens %6 mm, mindestens %7 mm</translation>
    </message>
    <message>
        <source>The program has no finishing moves (see the G-code&apos;s warnings): the finishing time is taken as zero.</source>
        <translation>Das Programm hat keine Schlichtbewegungen (siehe die Warnungen des G-Codes): die Schlichtzeit wird als null angenommen.</translation>
    </message>
    <message>
        <source>The bores are not in the finishing time: the program does not bore them (see the G-code&apos;s notes).</source>
        <translation>Die Bohrungen sind nicht in der Schlichtzeit: das Programm dreht sie nicht aus (siehe die Hinweise des G-Codes).</translation>
    </message>
    <message>
        <source>Not among the plan&apos;s constraints: %1.</source>
        <translation>Nicht unter den Nebenbedingungen des Plans: %1.</translation>
    </message>
    <message>
        <source>%1, the boring bar&apos;s insert</source>
        <translation>%1, die Wendeschneidplatte der Bohrstange</translation>
    </message>
</context>
<context>
    <name>Plausibility</name>
    <message>
        <source>unknown material &quot;%1&quot;; the data library has: %2</source>
        <translation>unbekannter Werkstoff „%1“; die Datenbibliothek enthält: %2</translation>
    </message>
    <message>
        <source>unknown machine &quot;%1&quot;; the data library has: %2</source>
        <translation>unbekannte Maschine „%1“; die Datenbibliothek enthält: %2</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library and its ISO 5608 style letter (third character) gives no known entering angle</source>
        <translation>Halter „%1“ ist nicht in der Datenbibliothek, und sein ISO-5608-Formbuchstabe (drittes Zeichen) ergibt keinen bekannten Einstellwinkel</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library: its entering angle comes from its ISO 5608 style letter, and its shank is not in the toolpost term</source>
        <translation>Halter „%1“ ist nicht in der Datenbibliothek: sein Einstellwinkel stammt aus dem ISO-5608-Formbuchstaben, und sein Schaft fehlt im Werkzeughalterterm</translation>
    </message>
    <message>
        <source>%1 %2 is outside the insert&apos;s published range %3–%4 %2 (%5)</source>
        <translation>%1 %2 liegt außerhalb des veröffentlichten Bereichs der Wendeschneidplatte %3–%4 %2 (%5)</translation>
    </message>
    <message>
        <source>no source given</source>
        <translation>keine Quelle angegeben</translation>
    </message>
    <message>
        <source>%1 m/min on Ø%2 mm needs %3 rpm, more than the machine&apos;s %4 rpm: the spindle speed limit lowers the cutting speed there</source>
        <translation>%1 m/min auf Ø%2 mm braucht %3 1/min, mehr als die %4 1/min der Maschine: die Drehzahlgrenze senkt dort die Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>the pass needs %1 kW of cutting power, more than the machine&apos;s %2 kW</source>
        <translation>der Schnitt braucht %1 kW Schnittleistung, mehr als die %2 kW der Maschine</translation>
    </message>
    <message>
        <source>the passes cut %1 mm deep in all, but the stock is at most %2 mm thick on the radius (Ø%3 mm bar, smallest turned Ø%4 mm): the tool cuts air for %5 mm, and the forces and deflection are not those of the passes as given</source>
        <translation>die Schnitte schneiden insgesamt %1 mm tief, aber das Aufmaß ist auf dem Radius höchstens %2 mm dick (Stange Ø%3 mm, kleinster gedrehter Ø%4 mm): Das Werkzeug schneidet %5 mm Luft, und Kräfte und Durchbiegung sind nicht die der angegebenen Schnitte</translation>
    </message>
    <message>
        <source>the part has bores but no boring bar is given: they are computed as if cut by %1, without the bending of a bar</source>
        <translation>das Teil hat Bohrungen, aber keine Bohrstange ist angegeben: sie werden berechnet, als würden sie mit %1 bearbeitet, ohne die Biegung einer Stange</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar in the data library; it has: %2</source>
        <translation>&quot;%1&quot; ist keine Bohrstange in der Datenbibliothek; sie enthält: %2</translation>
    </message>
    <message>
        <source>the bar material of &quot;%1&quot; (type letter %2) is not in the data library</source>
        <translation>der Stangenwerkstoff von &quot;%1&quot; (Kennbuchstabe %2) ist nicht in der Datenbibliothek</translation>
    </message>
    <message>
        <source>%1 mm is %2 times the bar&apos;s diameter, more than the %3 times the maker allows a %4 bar (%5): expect chatter; use a carbide or a larger bar, or bore from both ends</source>
        <translation>%1 mm ist das %2-Fache des Stangendurchmessers, mehr als das %3-Fache, das der Hersteller für eine Stange aus %4 zulässt (%5): Rattern ist zu erwarten; eine Hartmetall- oder eine dickere Stange verwenden oder von beiden Seiten ausbohren</translation>
    </message>
    <message>
        <source>a boring bar is given but no bore is cut</source>
        <translation>eine Bohrstange ist angegeben, aber keine Bohrung wird bearbeitet</translation>
    </message>
    <message>
        <source>the groove between %1 and %2 is %3 mm wide, narrower than the nose of %4 (r_e %5 mm, %6 mm across): it cannot reach the groove&apos;s bottom; cut the groove with a grooving insert at most %3 mm wide</source>
        <translation>der Einstich zwischen %1 und %2 ist %3 mm breit, schmaler als die Schneidenecke von %4 (r_e %5 mm, %6 mm breit): sie erreicht den Grund des Einstichs nicht; den Einstich mit einer Einstechplatte von höchstens %3 mm Breite bearbeiten</translation>
    </message>
    <message>
        <source>an edge %1 mm off the bar&apos;s axis cannot cut inside a bore: the widest is Ø%2 mm</source>
        <translation>eine Schneide %1 mm neben der Achse der Bohrstange kann in keiner Bohrung schneiden: die weiteste hat Ø%2 mm</translation>
    </message>
    <message>
        <source>a pilot hole of Ø%1 mm leaves nothing to bore in %2, Ø%3 mm</source>
        <translation>eine Vorbohrung von Ø%1 mm lässt in %2, Ø%3 mm, nichts auszudrehen</translation>
    </message>
    <message>
        <source>no finishing pass: the last pass is taken as the one that cuts the contour to size (the verdicts and the program rest on it)</source>
        <translation>kein Schlichtschnitt: der letzte Schnitt wird als der genommen, der die Kontur auf Maß schneidet (die Urteile und das Programm beruhen darauf)</translation>
    </message>
    <message>
        <source>left at the pilot hole</source>
        <translation>bleibt auf dem Maß der Vorbohrung</translation>
    </message>
    <message>
        <source>inside the jaws (left of z = %1 mm), where no verdict judges it</source>
        <translation>innerhalb der Backen (links von z = %1 mm), wo keine Bewertung sie beurteilt</translation>
    </message>
    <message>
        <source>while the verdicts of %1 take it as bored</source>
        <translation>während die Bewertungen von %1 sie als gebohrt nehmen</translation>
    </message>
    <message>
        <source>%1 mm reaches z = %2 mm (the free end at %3 mm, %4 mm clear of it): %5 not bored from z = %6 mm to there, %7. Reaching it needs an overhang of %8 mm; or bore from both ends</source>
        <translation>%1 mm reicht bis z = %2 mm (das freie Ende bei %3 mm, %4 mm Abstand davon): %5 von z = %6 mm bis dorthin nicht gebohrt, %7. Um es zu erreichen, braucht es eine Auskraglänge von %8 mm; oder von beiden Enden bohren</translation>
    </message>
    <message>
        <source>bore %1</source>
        <translation>Bohrung %1</translation>
    </message>
    <message>
        <source>bores %1</source>
        <translation>Bohrungen %1</translation>
    </message>
</context>
<context>
    <name>PlotExport</name>
    <message>
        <source>cannot export a plot as &apos;%1&apos;: use .png, .svg or .pdf</source>
        <translation>Diagramm kann nicht als „%1“ exportiert werden: verwenden Sie .png, .svg oder .pdf</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg);;PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Copy Data as CSV</source>
        <translation>Daten als CSV kopieren</translation>
    </message>
    <message>
        <source>Export Image…</source>
        <translation>Bild exportieren…</translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
</context>
<context>
    <name>PostProcessor</name>
    <message>
        <source>Path of the imaginary tool tip for nose radius %1 mm, computed by TolTurn: no G41/G42; set the nose radius to 0 in the tool offsets</source>
        <translation>Bahn der theoretischen Schneidenspitze für den Eckenradius %1 mm, von TolTurn berechnet: kein G41/G42; Eckenradius in den Werkzeugkorrekturen auf 0 setzen</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 3</source>
        <translation>G42 Schneidenradiuskorrektur: Schneide D1 mit Radius %1 mm, Schneidenlage 3</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: tool table diameter D%1, orientation Q2</source>
        <translation>G42 Schneidenradiuskorrektur: Werkzeugtabelle Durchmesser D%1, Orientierung Q2</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: radius %1 mm and tip 3 in the tool geometry offset</source>
        <translation>G42 Schneidenradiuskorrektur: Radius %1 mm und Schneidenlage 3 in der Werkzeuggeometrie</translation>
    </message>
    <message>
        <source>Pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</source>
        <translation>Schnitt %1, %2: vc %3 m/min, f %4 mm/U, ap %5 mm</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>Schlichten</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>Schruppen</translation>
    </message>
    <message>
        <source>Siemens Sinumerik</source>
        <translation>Siemens Sinumerik</translation>
    </message>
    <message>
        <source>LinuxCNC</source>
        <translation>LinuxCNC</translation>
    </message>
    <message>
        <source>Fanuc / Haas</source>
        <translation>Fanuc / Haas</translation>
    </message>
    <message>
        <source>Highest speed the plan needs: vc %1 m/min on D%2 mm</source>
        <translation>Höchste Drehzahl, die der Plan braucht: vc %1 m/min auf D%2 mm</translation>
    </message>
    <message>
        <source>Machine limit %1 rpm; the plan would need %2 rpm on D%3 mm</source>
        <translation>Maschinengrenze %1 1/min; der Plan bräuchte %2 1/min auf D%3 mm</translation>
    </message>
    <message>
        <source>; machine limit %1 rpm</source>
        <translation>; Maschinengrenze %1 1/min</translation>
    </message>
    <message>
        <source>; the machine&apos;s limit is not known</source>
        <translation>; die Grenze der Maschine ist nicht bekannt</translation>
    </message>
    <message>
        <source>Z0 at the right end face, X on diameter, G02/G03 seen with Z to the right and X up</source>
        <translation>Z0 an der rechten Stirnfläche, X im Durchmesser, G02/G03 gesehen mit Z nach rechts und X nach oben</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Boring bar: path of the imaginary tool tip for nose radius %1 mm (tip 2), computed by TolTurn: no G41/G42; set the nose radius to 0 in its tool offsets</source>
        <translation>Bohrstange: Bahn der theoretischen Schneidenspitze für Eckenradius %1 mm (Schneidenlage 2), von TolTurn berechnet: kein G41/G42; Eckenradius in ihren Werkzeugkorrekturen auf 0 setzen</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 2</source>
        <translation>G41 Schneidenradiuskorrektur: Schneide D1 mit Radius %1 mm, Schneidenlage 2</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: tool table diameter D%1, orientation Q3</source>
        <translation>G41 Schneidenradiuskorrektur: Werkzeugtabelle Durchmesser D%1, Orientierung Q3</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: radius %1 mm and tip 2 in the tool geometry offset</source>
        <translation>G41 Schneidenradiuskorrektur: Radius %1 mm und Schneidenlage 2 in der Werkzeuggeometrie</translation>
    </message>
    <message>
        <source>Bore pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</source>
        <translation>Bohrschnitt %1, %2: vc %3 m/min, f %4 mm/U, ap %5 mm</translation>
    </message>
    <message>
        <source>Clear of the part for the tool change: the boring bar&apos;s overhang and the clearance off the end face, above the turning path (or the machine&apos;s own tool-change position)</source>
        <translation>Frei vom Teil für den Werkzeugwechsel: Auskraglänge der Bohrstange und Abstand von der Stirnfläche, über der Drehbahn (oder die Werkzeugwechselposition der Maschine)</translation>
    </message>
</context>
<context>
    <name>ProfileChains</name>
    <message>
        <source>left end face</source>
        <translation>linke Stirnfläche</translation>
    </message>
    <message>
        <source>right end face</source>
        <translation>rechte Stirnfläche</translation>
    </message>
    <message>
        <source>shoulder</source>
        <translation>Absatzfläche</translation>
    </message>
    <message>
        <source>cylinder %1</source>
        <translation>Zylinder %1</translation>
    </message>
    <message>
        <source>cone</source>
        <translation>Kegel</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>Fase</translation>
    </message>
    <message>
        <source>radius R%1</source>
        <translation>Radius R%1</translation>
    </message>
    <message>
        <source>bore bottom</source>
        <translation>Bohrungsgrund</translation>
    </message>
    <message>
        <source>bore step</source>
        <translation>Bohrungsabsatz</translation>
    </message>
    <message>
        <source>bore %1</source>
        <translation>Bohrung %1</translation>
    </message>
    <message>
        <source>drill point</source>
        <translation>Bohrspitze</translation>
    </message>
    <message>
        <source>bore cone</source>
        <translation>Bohrungskegel</translation>
    </message>
    <message>
        <source>bore chamfer</source>
        <translation>Bohrungsfase</translation>
    </message>
    <message>
        <source>bore radius R%1</source>
        <translation>Bohrungsradius R%1</translation>
    </message>
    <message>
        <source>the revolved face %1 (from z = %2 mm to z = %3 mm, r = %4 to %5 mm) does not join the outer or inner contour (a closed inner cavity, or faces beyond a gap in the section) and is left out of the profile</source>
        <translation>die Rotationsfläche %1 (von z = %2 mm bis z = %3 mm, r = %4 bis %5 mm) schließt weder an die Außen- noch an die Innenkontur an (ein geschlossener innerer Hohlraum oder Flächen jenseits einer Lücke im Längsschnitt) und wird im Profil weggelassen</translation>
    </message>
    <message>
        <source>the revolved faces do not form a closed section from the left end (z = %1 mm) to the right end (z = %2 mm): the contour from the left end stops at z = %3 mm, r = %4 mm, where a face is missing or not turned (see the warnings)</source>
        <translation>die Rotationsflächen bilden keinen geschlossenen Längsschnitt vom linken Ende (z = %1 mm) bis zum rechten Ende (z = %2 mm): die Kontur vom linken Ende bricht bei z = %3 mm, r = %4 mm ab, wo eine Fläche fehlt oder nicht gedreht ist (siehe die Warnungen)</translation>
    </message>
</context>
<context>
    <name>ProfileEditing</name>
    <message>
        <source>the %1 contour has no vertex %2</source>
        <translation>die Kontur %1 hat keinen Eckpunkt %2</translation>
    </message>
    <message>
        <source>a step is inserted into a cylinder; %1 is not one</source>
        <translation>ein Absatz wird in einen Zylinder eingefügt; %1 ist keiner</translation>
    </message>
    <message>
        <source>the step of %1 must lie inside it (z %2 … %3 mm), but z is %4 mm</source>
        <translation>der Absatz in %1 muss innerhalb davon liegen (z %2 … %3 mm), z beträgt aber %4 mm</translation>
    </message>
    <message>
        <source>the step&apos;s diameter must differ from Ø%1 mm and be above zero, but is %2 mm</source>
        <translation>der Durchmesser des Absatzes muss sich von Ø%1 mm unterscheiden und größer als null sein, beträgt aber %2 mm</translation>
    </message>
    <message>
        <source>step face</source>
        <translation>Absatzfläche</translation>
    </message>
    <message>
        <source>step diameter</source>
        <translation>Absatzdurchmesser</translation>
    </message>
    <message>
        <source>vertex %1 of the %2 contour is not a corner between two features</source>
        <translation>Eckpunkt %1 der Kontur %2 ist keine Ecke zwischen zwei Formelementen</translation>
    </message>
    <message>
        <source>a corner is broken between a face and a cylinder; %1 and %2 are not</source>
        <translation>eine Ecke wird zwischen einer Planfläche und einem Zylinder gebrochen; %1 und %2 sind das nicht</translation>
    </message>
    <message>
        <source>the corner of %1 and %2 takes at most %3 mm, but the size is %4 mm</source>
        <translation>die Ecke zwischen %1 und %2 erlaubt höchstens %3 mm, die Größe beträgt aber %4 mm</translation>
    </message>
    <message>
        <source>edge round</source>
        <translation>Kantenverrundung</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>Fase</translation>
    </message>
    <message>
        <source>a cone is made from a cylinder; %1 is not one</source>
        <translation>ein Kegel entsteht aus einem Zylinder; %1 ist keiner</translation>
    </message>
    <message>
        <source>the cone&apos;s end needs a diameter other than Ø%1 mm, but it is %2 mm</source>
        <translation>das Kegelende benötigt einen anderen Durchmesser als Ø%1 mm, er beträgt aber %2 mm</translation>
    </message>
    <message>
        <source>a cylinder is made from a cone; %1 is not one</source>
        <translation>ein Zylinder entsteht aus einem Kegel; %1 ist keiner</translation>
    </message>
    <message>
        <source>a bore starts at an end face of the part; %1 is not one</source>
        <translation>eine Bohrung beginnt an einer Stirnfläche des Teils; %1 ist keine</translation>
    </message>
    <message>
        <source>a bore needs a depth and a diameter above zero, but they are %1 and %2 mm</source>
        <translation>eine Bohrung benötigt eine Tiefe und einen Durchmesser größer als null, sie betragen aber %1 und %2 mm</translation>
    </message>
    <message>
        <source>bore</source>
        <translation>Bohrung</translation>
    </message>
    <message>
        <source>bore bottom</source>
        <translation>Bohrungsgrund</translation>
    </message>
    <message>
        <source>there is no feature %1</source>
        <translation>es gibt kein Formelement %1</translation>
    </message>
    <message>
        <source>the features beside %1 are parallel: there is no corner to give back</source>
        <translation>die Formelemente neben %1 sind parallel: es gibt keine Ecke, die wiederhergestellt werden kann</translation>
    </message>
    <message>
        <source>only a chamfer or an edge round changes into the other; %1 is neither</source>
        <translation>nur eine Fase oder eine Kantenrundung lässt sich in die andere umwandeln; %1 ist keines von beiden</translation>
    </message>
    <message>
        <source>moving the corner would make %1 turn back along z (an undercut), which needs an undercut insert; move it less, or insert a DIN 509 undercut</source>
        <translation>das Verschieben der Ecke würde %1 entlang z zurücklaufen lassen (ein Freistich), wofür eine Freistichplatte nötig ist; die Ecke weniger verschieben oder einen Freistich nach DIN 509 einfügen</translation>
    </message>
    <message>
        <source>the part is bored from this end already (or through); edit its bore instead</source>
        <translation>das Teil ist von diesem Ende aus bereits gebohrt (oder durchgebohrt); stattdessen seine Bohrung ändern</translation>
    </message>
    <message>
        <source>a bore %1 mm deep would meet the bore from the other end, whose bottom is at z = %2 mm: leave solid between them, or make it one through bore</source>
        <translation>eine Bohrung von %1 mm Tiefe würde auf die Bohrung vom anderen Ende treffen, deren Grund bei z = %2 mm liegt: Material zwischen ihnen stehen lassen oder eine durchgehende Bohrung daraus machen</translation>
    </message>
    <message>
        <source>%1 is an end of the %2 contour (or of a bore); move it instead of deleting it</source>
        <translation>%1 ist ein Ende der Kontur (%2) oder einer Bohrung; verschieben statt löschen</translation>
    </message>
</context>
<context>
    <name>ProfileValidation</name>
    <message>
        <source>the coordinate is not a finite number</source>
        <translation>die Koordinate ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>must not be negative, but is %1 mm</source>
        <translation>darf nicht negativ sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>a cylinder keeps one radius, but this one goes from r = %1 mm to r = %2 mm (a cone?)</source>
        <translation>ein Zylinder hat einen konstanten Radius, dieser verläuft aber von r = %1 mm bis r = %2 mm (ein Kegel?)</translation>
    </message>
    <message>
        <source>the cylinder has zero length: it starts and ends at z = %1 mm</source>
        <translation>der Zylinder hat die Länge null: er beginnt und endet bei z = %1 mm</translation>
    </message>
    <message>
        <source>a cylinder needs a radius above zero, but r = %1 mm</source>
        <translation>ein Zylinder benötigt einen Radius größer als null, aber r = %1 mm</translation>
    </message>
    <message>
        <source>a face stays at one z, but this one goes from z = %1 mm to z = %2 mm (a cone?)</source>
        <translation>eine Planfläche bleibt auf einem z-Wert, diese verläuft aber von z = %1 mm bis z = %2 mm (ein Kegel?)</translation>
    </message>
    <message>
        <source>the face has zero length: it starts and ends at r = %1 mm</source>
        <translation>die Planfläche hat die Länge null: sie beginnt und endet bei r = %1 mm</translation>
    </message>
    <message>
        <source>a %1 must change radius, but it stays at r = %2 mm (a cylinder?)</source>
        <translation>ein Segment vom Typ %1 muss den Radius ändern, bleibt aber bei r = %2 mm (ein Zylinder?)</translation>
    </message>
    <message>
        <source>the radius must be above zero, but is %1 mm</source>
        <translation>der Radius muss größer als null sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>the radius has zero length: both ends are at %1</source>
        <translation>der Radius hat die Länge null: beide Enden liegen bei %1</translation>
    </message>
    <message>
        <source>a radius of %1 mm cannot join two points %2 mm apart (it needs at least %3 mm)</source>
        <translation>ein Radius von %1 mm kann keine zwei Punkte im Abstand von %2 mm verbinden (er muss mindestens %3 mm betragen)</translation>
    </message>
    <message>
        <source>overlaps %1: it starts at %2, left of where %1 ends, %3</source>
        <translation>überlappt %1: beginnt bei %2, links von %3, wo %1 endet</translation>
    </message>
    <message>
        <source>leaves a gap: it starts at %2, but %1 ends at %3</source>
        <translation>lässt eine Lücke: beginnt bei %2, %1 endet aber bei %3</translation>
    </message>
    <message>
        <source>the face turns back over %1 at z = %2 mm: the two faces overlap</source>
        <translation>die Planfläche läuft bei z = %2 mm über %1 zurück: die beiden Planflächen überlappen sich</translation>
    </message>
    <message>
        <source>the outer contour must start at the left end of the part, z = 0 mm, but starts at z = %1 mm</source>
        <translation>die Außenkontur muss am linken Ende des Teils bei z = 0 mm beginnen, beginnt aber bei z = %1 mm</translation>
    </message>
    <message>
        <source>the part has zero length: the outer contour ends at z = %1 mm</source>
        <translation>das Teil hat die Länge null: die Außenkontur endet bei z = %1 mm</translation>
    </message>
    <message>
        <source>the left end face must start at r = %1 mm (%2), but starts at r = %3 mm</source>
        <translation>die linke Stirnfläche muss bei r = %1 mm beginnen (%2), beginnt aber bei r = %3 mm</translation>
    </message>
    <message>
        <source>the bore</source>
        <translation>die Bohrung</translation>
    </message>
    <message>
        <source>the axis</source>
        <translation>die Achse</translation>
    </message>
    <message>
        <source>the right end face must end at r = %1 mm (%2), but ends at r = %3 mm</source>
        <translation>die rechte Stirnfläche muss bei r = %1 mm enden (%2), endet aber bei r = %3 mm</translation>
    </message>
    <message>
        <source>the inner contour must start at the left end (z = 0 mm) or on the axis (r = 0 mm), but starts at %1</source>
        <translation>die Innenkontur muss am linken Ende (z = 0 mm) oder auf der Achse (r = 0 mm) beginnen, beginnt aber bei %1</translation>
    </message>
    <message>
        <source>the inner contour must end at the right end (z = %1 mm) or on the axis (r = 0 mm), but ends at %2</source>
        <translation>die Innenkontur muss am rechten Ende (z = %1 mm) oder auf der Achse (r = 0 mm) enden, endet aber bei %2</translation>
    </message>
    <message>
        <source>the bore ends at z = %1 mm, beyond the right end of the part at z = %2 mm</source>
        <translation>die Bohrung endet bei z = %1 mm, jenseits des rechten Teilendes bei z = %2 mm</translation>
    </message>
    <message>
        <source>the bore reaches r = %1 mm at z = %2 mm, where the outer contour is at r = %3 mm: the inner radius meets the outer one</source>
        <translation>die Bohrung erreicht r = %1 mm bei z = %2 mm, wo die Außenkontur bei r = %3 mm liegt: der Innenradius trifft auf den Außenradius</translation>
    </message>
    <message>
        <source>every feature needs an id, but this one is empty</source>
        <translation>jedes Formelement benötigt eine ID, diese ist aber leer</translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used by another feature; ids must be unique</source>
        <translation>die ID „%1“ wird von einem anderen Formelement verwendet; IDs müssen eindeutig sein</translation>
    </message>
    <message>
        <source>the stock diameter must be above zero, but is %1 mm</source>
        <translation>der Rohteildurchmesser muss größer als null sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>the outer contour has no segments</source>
        <translation>die Außenkontur hat keine Segmente</translation>
    </message>
    <message>
        <source>the stock diameter %1 mm is smaller than the part, whose largest diameter is %2 mm</source>
        <translation>der Rohteildurchmesser %1 mm ist kleiner als das Teil, dessen größter Durchmesser %2 mm beträgt</translation>
    </message>
    <message>
        <source>the cylinder runs backwards along z, from z = %1 mm to z = %2 mm: a contour runs from left to right, and only an undercut&apos;s cones and radii may go back</source>
        <translation>der Zylinder verläuft entlang z rückwärts, von z = %1 mm bis z = %2 mm: eine Kontur verläuft von links nach rechts, und nur die Kegel und Radien eines Freistichs dürfen zurücklaufen</translation>
    </message>
    <message>
        <source>a %1 must move along z, but it starts and ends at z = %2 mm (a face?)</source>
        <translation>ein Formelement vom Typ %1 muss entlang z verlaufen, beginnt und endet aber bei z = %2 mm (eine Planfläche?)</translation>
    </message>
    <message>
        <source>the inner contour leaves the axis a second time at z = %1 mm: a part has at most one bore from each end</source>
        <translation>die Innenkontur verlässt die Achse ein zweites Mal bei z = %1 mm: ein Teil hat höchstens eine Bohrung von jedem Ende</translation>
    </message>
    <message>
        <source>the bores from both ends meet on the axis at z = %1 mm, leaving no solid between them: make them one through bore, stepped by a face from r = %2 mm to r = %3 mm</source>
        <translation>die Bohrungen von beiden Enden treffen sich auf der Achse bei z = %1 mm, ohne Material dazwischen: eine durchgehende Bohrung daraus machen, abgesetzt durch eine Planfläche von r = %2 mm auf r = %3 mm</translation>
    </message>
    <message>
        <source>the bore from z = %1 mm to z = %2 mm is closed at both ends (a cavity that no tool can reach): it must open at z = 0 mm or at z = %3 mm</source>
        <translation>die Bohrung von z = %1 mm bis z = %2 mm ist an beiden Enden geschlossen (ein Hohlraum, den kein Werkzeug erreicht): sie muss sich bei z = 0 mm oder bei z = %3 mm öffnen</translation>
    </message>
    <message>
        <source>crosses %1 at %2: the contour overlaps itself (an undercut deeper than the material around it?)</source>
        <translation>schneidet %1 bei %2: die Kontur überschneidet sich selbst (ein Freistich, der tiefer ist als das umgebende Material?)</translation>
    </message>
</context>
<context>
    <name>ProjectFile</name>
    <message>
        <source>&apos;%1&apos; does not exist</source>
        <translation>„%1“ existiert nicht</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a folder, not a project file</source>
        <translation>„%1“ ist ein Ordner, keine Projektdatei</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2 MiB, more than the %3 MiB a project file may have</source>
        <translation>„%1“ ist %2 MiB groß, mehr als die %3 MiB, die eine Projektdatei haben darf</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not written: the project would not open again (%2)</source>
        <translation>&apos;%1&apos; nicht geschrieben: Das Projekt ließe sich nicht wieder öffnen (%2)</translation>
    </message>
</context>
<context>
    <name>ProjectJson</name>
    <message>
        <source>segment type</source>
        <translation>Segmenttyp</translation>
    </message>
    <message>
        <source>arc direction</source>
        <translation>Bogenrichtung</translation>
    </message>
    <message>
        <source>expected a segment object, found %1</source>
        <translation>erwartet: ein Segmentobjekt, gefunden: %1</translation>
    </message>
    <message>
        <source>force model</source>
        <translation>Kraftmodell</translation>
    </message>
    <message>
        <source>objective</source>
        <translation>Zielfunktion</translation>
    </message>
    <message>
        <source>clamping method</source>
        <translation>Spannart</translation>
    </message>
    <message>
        <source>expected an object, found %1</source>
        <translation>erwartet: ein Objekt, gefunden: %1</translation>
    </message>
    <message>
        <source>pass kind</source>
        <translation>Schnittart</translation>
    </message>
    <message>
        <source>tolerance type</source>
        <translation>Toleranzart</translation>
    </message>
    <message>
        <source>this is not a TolTurn project: format is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>dies ist kein TolTurn-Projekt: das Format ist „%1“, erwartet wird „%2“</translation>
    </message>
    <message>
        <source>invalid JSON at line %1, column %2: %3</source>
        <translation>ungültiges JSON in Zeile %1, Spalte %2: %3</translation>
    </message>
    <message>
        <source>a project file holds one JSON object, not a list</source>
        <translation>eine Projektdatei enthält ein JSON-Objekt, keine Liste</translation>
    </message>
    <message>
        <source>part end</source>
        <translation>Teilende</translation>
    </message>
    <message>
        <source>unknown format version %1; this TolTurn reads versions 1 to %2</source>
        <translation>unbekannte Formatversion %1; dieses TolTurn liest die Versionen 1 bis %2</translation>
    </message>
    <message>
        <source>cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>milling direction</source>
        <translation>Fräsrichtung</translation>
    </message>
    <message>
        <source>milled tolerance type</source>
        <translation>Toleranzart des gefrästen Formelements</translation>
    </message>
    <message>
        <source>expected three numbers, found %1</source>
        <translation>erwartet: drei Zahlen, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>erwartet: eine Zahl, gefunden: %1</translation>
    </message>
    <message>
        <source>milled feature kind</source>
        <translation>Art des gefrästen Formelements</translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation>erwartet: %1, gefunden: %2</translation>
    </message>
    <message>
        <source>a constraint name</source>
        <translation>der Name einer Randbedingung</translation>
    </message>
    <message>
        <source>a feature id</source>
        <translation>eine Formelement-ID</translation>
    </message>
    <message>
        <source>a datum letter</source>
        <translation>ein Bezugsbuchstabe</translation>
    </message>
</context>
<context>
    <name>ProjectValidation</name>
    <message>
        <source>%1 is missing (empty)</source>
        <translation>%1 fehlt (leer)</translation>
    </message>
    <message>
        <source>must be zero or more, but is %1 mm</source>
        <translation>muss null oder größer sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>a part held in a chuck needs a clamped length above zero, but it is %1 mm</source>
        <translation>ein im Futter gespanntes Teil benötigt eine Einspannlänge größer als null, sie beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>the clamped length %1 mm leaves nothing to turn on a part %2 mm long</source>
        <translation>die Einspannlänge %1 mm lässt an einem %2 mm langen Teil nichts zum Drehen übrig</translation>
    </message>
    <message>
        <source>a part between centres is not clamped; the clamped length %1 mm is ignored</source>
        <translation>ein Teil zwischen Spitzen ist nicht eingespannt; die Einspannlänge %1 mm wird ignoriert</translation>
    </message>
    <message>
        <source>must be above zero, but is %1</source>
        <translation>muss größer als null sein, beträgt aber %1</translation>
    </message>
    <message>
        <source>a datum is named by one or two capital letters (ISO 5459), not &apos;%1&apos;</source>
        <translation>ein Bezug wird mit einem oder zwei Großbuchstaben bezeichnet (ISO 5459), nicht „%1“</translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is defined twice</source>
        <translation>Bezug „%1“ ist doppelt definiert</translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation>im Profil gibt es kein Formelement „%1“</translation>
    </message>
    <message>
        <source>give either an ISO 286 class or both limit deviations (upper_um, lower_um)</source>
        <translation>geben Sie entweder eine Toleranzklasse nach ISO 286 oder beide Grenzabmaße an (upper_um, lower_um)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an ISO 286 tolerance class (a letter and a grade, e.g. h6 or H7)</source>
        <translation>„%1“ ist keine Toleranzklasse nach ISO 286 (ein Buchstabe und ein Grad, z. B. h6 oder H7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a shaft class, but feature &apos;%2&apos; is a bore: use capital letters (e.g. H7)</source>
        <translation>„%1“ ist eine Wellenklasse, Formelement „%2“ ist aber eine Bohrung: verwenden Sie Großbuchstaben (z. B. H7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a hole class, but feature &apos;%2&apos; is an outer surface: use small letters (e.g. h6)</source>
        <translation>„%1“ ist eine Bohrungsklasse, Formelement „%2“ ist aber eine Außenfläche: verwenden Sie Kleinbuchstaben (z. B. h6)</translation>
    </message>
    <message>
        <source>both limit deviations are needed, upper_um and lower_um</source>
        <translation>beide Grenzabmaße werden benötigt, upper_um und lower_um</translation>
    </message>
    <message>
        <source>the upper deviation %1 µm must be above the lower deviation %2 µm</source>
        <translation>das obere Grenzabmaß %1 µm muss größer als das untere Grenzabmaß %2 µm sein</translation>
    </message>
    <message>
        <source>a %1 tolerance needs a zone width above zero, but it is %2</source>
        <translation>eine Toleranz vom Typ %1 benötigt eine Toleranzzonenbreite größer als null, angegeben: %2</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>a %1 tolerance is defined relative to a datum, but none is given</source>
        <translation>eine Toleranz vom Typ %1 bezieht sich auf einen Bezug, es ist aber keiner angegeben</translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is not defined in the project&apos;s datums</source>
        <translation>Bezug „%1“ ist in den Bezügen des Projekts nicht definiert</translation>
    </message>
    <message>
        <source>a %1 tolerance cannot sit on feature &apos;%2&apos;, which is a %3</source>
        <translation>eine Toleranz vom Typ %1 kann nicht an Formelement „%2“ angebracht werden, das vom Typ %3 ist</translation>
    </message>
    <message>
        <source>a length runs between two faces; there is no feature &apos;%1&apos; in the profile</source>
        <translation>ein Längenmaß verläuft zwischen zwei Planflächen; im Profil gibt es kein Formelement „%1“</translation>
    </message>
    <message>
        <source>a length runs between two different faces; &apos;%1&apos; is not one</source>
        <translation>ein Längenmaß verläuft zwischen zwei verschiedenen Planflächen; „%1“ ist keine</translation>
    </message>
    <message>
        <source>every tolerance needs an id, but this one is empty</source>
        <translation>jede Toleranz benötigt eine ID, diese ist aber leer</translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used twice</source>
        <translation>die ID „%1“ wird doppelt verwendet</translation>
    </message>
    <message>
        <source>must be zero or more, but is %1</source>
        <translation>muss null oder größer sein, beträgt aber %1</translation>
    </message>
    <message>
        <source>the li_du force model needs normal_pressure_MPa (K_n) and friction_ratio (K_f); fit them from measured forces with &apos;tolturn-cli calibrate-forces&apos;</source>
        <translation>das Kraftmodell li_du benötigt normal_pressure_MPa (K_n) und friction_ratio (K_f); passen Sie diese mit &apos;tolturn-cli calibrate-forces&apos; an gemessene Kräfte an</translation>
    </message>
    <message>
        <source>where the machine characterisation comes from</source>
        <translation>die Herkunft der Maschinencharakterisierung</translation>
    </message>
    <message>
        <source>spindle springs need the pivot distance Lc of the k2 spring behind the chuck face</source>
        <translation>Spindelfedern benötigen den Drehpunktabstand Lc der k2-Feder hinter der Futterstirnfläche</translation>
    </message>
    <message>
        <source>must be at least the minimum %1, but is %2</source>
        <translation>muss mindestens das Minimum %1 betragen, beträgt aber %2</translation>
    </message>
    <message>
        <source>the Taylor exponent n lies between 0 and 1, but is %1</source>
        <translation>der Taylor-Exponent n liegt zwischen 0 und 1, beträgt aber %1</translation>
    </message>
    <message>
        <source>the source of the Taylor constants</source>
        <translation>die Quelle der Taylor-Konstanten</translation>
    </message>
    <message>
        <source>the source of the cutting ranges</source>
        <translation>die Quelle der Schnittwertbereiche</translation>
    </message>
    <message>
        <source>unknown constraint &quot;%1&quot;; the constraints are: %2</source>
        <translation>unbekannte Randbedingung „%1“; die Randbedingungen sind: %2</translation>
    </message>
    <message>
        <source>the work material</source>
        <translation>der Werkstoff</translation>
    </message>
    <message>
        <source>the machine</source>
        <translation>die Maschine</translation>
    </message>
    <message>
        <source>the insert code</source>
        <translation>die Bezeichnung der Wendeschneidplatte</translation>
    </message>
    <message>
        <source>give both Taylor constants C and n, or neither</source>
        <translation>beide Taylor-Konstanten C und n angeben oder keine</translation>
    </message>
    <message>
        <source>must be above absolute zero (-273.15 °C), but is %1 °C</source>
        <translation>muss über dem absoluten Nullpunkt (-273,15 °C) liegen, ist aber %1 °C</translation>
    </message>
    <message>
        <source>the boring bar&apos;s insert code</source>
        <translation>der Wendeschneidplattencode der Bohrstange</translation>
    </message>
    <message>
        <source>the boring bar</source>
        <translation>die Bohrstange</translation>
    </message>
    <message>
        <source>only a boring bar starts from a pilot hole: give it in boring_tool</source>
        <translation>nur eine Bohrstange beginnt an einer Vorbohrung: geben Sie sie in boring_tool an</translation>
    </message>
    <message>
        <source>ISO 286 gives no limits for %1 at Ø%2 mm: %3</source>
        <translation>ISO 286 nennt für %1 bei Ø%2 mm keine Grenzabmaße: %3</translation>
    </message>
    <message>
        <source>not given: the thermal drift is computed for a machine warmed through, the largest drift; give the time since the machine started</source>
        <translation>nicht angegeben: die Wärmedrift wird für eine durchgewärmte Maschine berechnet, die größte Drift; geben Sie die Zeit seit dem Start der Maschine an</translation>
    </message>
    <message>
        <source>not given: taken as the characterisation&apos;s reference temperature, %1 °C, so no drift from it</source>
        <translation>nicht angegeben: als Bezugstemperatur der Charakterisierung angenommen, %1 °C, also keine Drift durch sie</translation>
    </message>
    <message>
        <source>least cost needs the machine and operator rate per minute, but it is 0 (or not given)</source>
        <translation>minimale Kosten brauchen den Maschinen- und Bedienerstundensatz je Minute, er ist aber 0 (oder nicht angegeben)</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 allow no common size: one needs at most %2 µm, another at least %3 µm</source>
        <translation>die Maßtoleranzen des Formelements %1 lassen kein gemeinsames Maß zu: eine verlangt höchstens %2 µm, eine andere mindestens %3 µm</translation>
    </message>
    <message>
        <source>%1 is below %2, the least the program can state; it would be written as zero</source>
        <translation>%1 liegt unter %2, dem kleinsten Wert, den das Programm angeben kann; er würde als null geschrieben</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 leave a zone of no width (both limits at %2 µm), which no cut can hold</source>
        <translation>die Maßtoleranzen von Element %1 lassen eine Zone ohne Breite (beide Grenzen bei %2 µm), die kein Schnitt halten kann</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 leave a zone from %2 to %3 µm, narrower than the 1 µm step of the program&apos;s diameters: no program can aim into it</source>
        <translation>die Maßtoleranzen von Element %1 lassen eine Zone von %2 bis %3 µm, schmaler als der Schritt von 1 µm der Durchmesser im Programm: kein Programm kann hineinzielen</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Datum %1</source>
        <translation>Bezug %1</translation>
    </message>
</context>
<context>
    <name>RangeVerdicts</name>
    <message>
        <source>≥ %1 N/µm</source>
        <translation>≥ %1 N/µm</translation>
    </message>
    <message>
        <source>any</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>not reachable</source>
        <translation>nicht erreichbar</translation>
    </message>
    <message>
        <source>passes on any machine in the range</source>
        <translation>erfüllt auf jeder Maschine des Bereichs</translation>
    </message>
    <message>
        <source>passes only if the machine is stiffer than %1 N/µm</source>
        <translation>erfüllt nur, wenn die Maschine steifer als %1 N/µm ist</translation>
    </message>
    <message>
        <source>passes only on the stiffer machines of the range</source>
        <translation>erfüllt nur auf den steiferen Maschinen des Bereichs</translation>
    </message>
    <message>
        <source>chuck not measured: radial stiffness %1–%2 N/µm at the chuck face (%3), results at both ends, verdicts and plans at the compliant end</source>
        <translation>Futter nicht gemessen: radiale Steifigkeit %1–%2 N/µm an der Futterstirn (%3), Ergebnisse an beiden Enden, Bewertungen und Pläne am nachgiebigen Ende</translation>
    </message>
    <message>
        <source>spindle–chuck as measured</source>
        <translation>Spindel–Futter wie gemessen</translation>
    </message>
    <message>
        <source>chuck neither measured nor published: taken as rigid (optimistic)</source>
        <translation>Futter weder gemessen noch veröffentlicht: als starr angenommen (optimistisch)</translation>
    </message>
    <message>
        <source>tailstock and centres not measured and no published stiffness: taken as rigid (optimistic); see the stiffness each tolerance needs</source>
        <translation>Reitstock und Spitzen nicht gemessen und keine veröffentlichte Steifigkeit: als starr angenommen (optimistisch); siehe die Steifigkeit, die jede Toleranz braucht</translation>
    </message>
    <message>
        <source>%1–%2 N/µm only</source>
        <translation>nur %1–%2 N/µm</translation>
    </message>
    <message>
        <source>passes on the compliant machines of the range, not on the stiffest</source>
        <translation>erfüllt auf den nachgiebigen Maschinen des Bereichs, nicht auf der steifsten</translation>
    </message>
    <message>
        <source>tailstock as measured</source>
        <translation>Reitstock wie gemessen</translation>
    </message>
    <message>
        <source>headstock centre not measured and no published stiffness: taken as rigid (optimistic)</source>
        <translation>Spindelstockspitze nicht gemessen und keine veröffentlichte Steifigkeit: als starr angenommen (optimistisch)</translation>
    </message>
    <message>
        <source>thermal drift not measured: taken as zero (optimistic)</source>
        <translation>Wärmedrift nicht gemessen: als null angenommen (optimistisch)</translation>
    </message>
    <message>
        <source>spans set-ups: its error from clamping the part again (where it sits axially in the other set-up) is not known and not in this verdict. </source>
        <translation>über Aufspannungen hinweg: sein Fehler durch erneutes Spannen (wo das Teil in der anderen Aufspannung axial sitzt) ist nicht bekannt und nicht in dieser Bewertung. </translation>
    </message>
    <message>
        <source>collet not measured and no published stiffness: taken as rigid (optimistic); see the stiffness each tolerance needs</source>
        <translation>Spannzange nicht gemessen und keine veröffentlichte Steifigkeit: als starr angenommen (optimistisch); siehe die Steifigkeit, die jede Toleranz braucht</translation>
    </message>
    <message>
        <source>fails as programmed; an offset of %1 µm on the diameter holds it on any machine in the range</source>
        <translation>verfehlt wie programmiert; eine Korrektur von %1 µm am Durchmesser hält sie auf jeder Maschine des Bereichs</translation>
    </message>
    <message>
        <source>fails as programmed even on the stiffest machine of the range</source>
        <translation>verfehlt wie programmiert sogar auf der steifsten Maschine des Bereichs</translation>
    </message>
    <message>
        <source>%1; an offset of %2 µm on the diameter holds it on any machine in the range</source>
        <translation>%1; eine Korrektur von %2 µm am Durchmesser hält sie auf jeder Maschine des Bereichs</translation>
    </message>
    <message>
        <source>not finished by the program: %1</source>
        <translation>vom Programm nicht fertig bearbeitet: %1</translation>
    </message>
</context>
<context>
    <name>Remedies</name>
    <message>
        <source>, below the speed range, which starts at %1 m/min; at that speed it needs an insert grade with C of at least %2 m/min.</source>
        <translation>, unterhalb des Geschwindigkeitsbereichs, der bei %1 m/min beginnt; bei dieser Geschwindigkeit verlangt sie eine Schneidstoffsorte mit C von mindestens %2 m/min.</translation>
    </message>
    <message>
        <source>%1 (%2 mm)</source>
        <translation>%1 (%2 mm)</translation>
    </message>
    <message>
        <source>%1 ≤ %2 µm needs a feed of at most %3 mm/rev with the nose radius of %4</source>
        <translation>%1 ≤ %2 µm verlangt einen Vorschub von höchstens %3 mm/U mit dem Eckenradius von %4</translation>
    </message>
    <message>
        <source>, below the feed range, which starts at %1 mm/rev; at that feed it needs a nose radius of at least %2 mm on %3.</source>
        <translation>, unterhalb des Vorschubbereichs, der bei %1 mm/U beginnt; bei diesem Vorschub verlangt sie einen Eckenradius von mindestens %2 mm an %3.</translation>
    </message>
    <message>
        <source>A tool life of %1 min needs a cutting speed of at most %2 m/min (Taylor C = %3 m/min, n = %4)</source>
        <translation>Eine Standzeit von %1 min verlangt eine Schnittgeschwindigkeit von höchstens %2 m/min (Taylor C = %3 m/min, n = %4)</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>Tolerance report: %1</source>
        <translation>Toleranzbericht: %1</translation>
    </message>
    <message>
        <source>1  Part</source>
        <translation>1  Teil</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Eingabe</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Werkstoff</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Insert</source>
        <translation>Wendeschneidplatte</translation>
    </message>
    <message>
        <source>%1: %2° corner, nose radius %3 mm</source>
        <translation>%1: Eckenwinkel %2°, Eckenradius %3 mm</translation>
    </message>
    <message>
        <source>Holder</source>
        <translation>Halter</translation>
    </message>
    <message>
        <source>%1: entering angle %2°</source>
        <translation>%1: Einstellwinkel %2°</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Aufspannung</translation>
    </message>
    <message>
        <source>%1, clamped length %2 mm</source>
        <translation>%1, Einspannlänge %2 mm</translation>
    </message>
    <message>
        <source>Force model</source>
        <translation>Kraftmodell</translation>
    </message>
    <message>
        <source>Machine characterisation</source>
        <translation>Maschinencharakterisierung</translation>
    </message>
    <message>
        <source>3  Predicted deviation</source>
        <translation>3  Vorhergesagte Abweichung</translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [mm]</source>
        <translation>z ab linkem Teilende [mm]</translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation>Abweichung [µm]</translation>
    </message>
    <message>
        <source>Radial deviation of the outer contour (material left)</source>
        <translation>Radialabweichung der Außenkontur (stehen gebliebenes Material)</translation>
    </message>
    <message>
        <source>Radial deviation of the bores (material left)</source>
        <translation>Radialabweichung der Bohrungen (stehen gebliebenes Material)</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Planfläche</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>tan θ</source>
        <translation>tan θ</translation>
    </message>
    <message>
        <source>axial run-out e [µm]</source>
        <translation>Planlauf e [µm]</translation>
    </message>
    <message>
        <source>4  Tolerances</source>
        <translation>4  Toleranzen</translation>
    </message>
    <message>
        <source>The project has no tolerances.</source>
        <translation>Das Projekt enthält keine Toleranzen.</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Eigenschaft</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Spezifikation</translation>
    </message>
    <message>
        <source>Value [µm]</source>
        <translation>Wert [µm]</translation>
    </message>
    <message>
        <source>Limit [µm]</source>
        <translation>Grenze [µm]</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>Ausnutzung</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>optimum</source>
        <translation>Optimum</translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation>Vorschub f [mm/rev]</translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation>Schnittgeschwindigkeit vc [m/min]</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass (green: feasible)</source>
        <translation>Schnittwertfenster des Schlichtschnitts (grün: zulässig)</translation>
    </message>
    <message>
        <source>5  Plan</source>
        <translation>5  Plan</translation>
    </message>
    <message>
        <source>The project has no planning data (the insert&apos;s cutting ranges), so no plan was optimised.</source>
        <translation>Das Projekt enthält keine Planungsdaten (die Schnittwertbereiche der Wendeschneidplatte), daher wurde kein Plan optimiert.</translation>
    </message>
    <message>
        <source>Optimal plan (%1): </source>
        <translation>Optimaler Plan (%1): </translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one (%1): </source>
        <translation>Kein Plan erfüllt alle Randbedingungen; der Plan mit der geringsten Verletzung (%1): </translation>
    </message>
    <message>
        <source>Binding: %1.</source>
        <translation>Begrenzend: %1.</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>Rang</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Maßnahme</translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation>Korrektur Ø [µm]</translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation>Restabweichung vorher [µm]</translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation>Restabweichung nachher [µm]</translation>
    </message>
    <message>
        <source>Compensation of the project&apos;s finishing pass, only where a tolerance needs it:</source>
        <translation>Kompensation des Schlichtschnitts des Projekts, nur wo eine Toleranz es erfordert:</translation>
    </message>
    <message>
        <source>Material data (%1): %2</source>
        <translation>Werkstoffdaten (%1): %2</translation>
    </message>
    <message>
        <source>Elastic constants: %1</source>
        <translation>Elastische Konstanten: %1</translation>
    </message>
    <message>
        <source>Cutting ranges: %1</source>
        <translation>Schnittwertbereiche: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>TolTurn report: %1</source>
        <translation>TolTurn-Bericht: %1</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>Machine: %1.</source>
        <translation>Maschine: %1.</translation>
    </message>
    <message>
        <source>Verdicts</source>
        <translation>Bewertungen</translation>
    </message>
    <message>
        <source>On the machine range</source>
        <translation>Über den Maschinenbereich</translation>
    </message>
    <message>
        <source>Stiffness needed</source>
        <translation>Nötige Steifigkeit</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>not measured: see the machine assumption on page 1</source>
        <translation>nicht gemessen: siehe die Maschinenannahme auf Seite 1</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <source>Drawing no.</source>
        <translation>Zeichnungsnr.</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>Planner</source>
        <translation>Planer</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Approved (name, date)</source>
        <translation>Freigegeben (Name, Datum)</translation>
    </message>
    <message>
        <source>Project %1 · written %2 · TolTurn %3 · length %4 mm, stock Ø%5 mm</source>
        <translation>Projekt %1 · erstellt %2 · TolTurn %3 · Länge %4 mm, Rohteil Ø%5 mm</translation>
    </message>
    <message>
        <source>2  Set-up sheet and inputs</source>
        <translation>2  Einrichteblatt und Eingaben</translation>
    </message>
    <message>
        <source>programmed</source>
        <translation>programmiert</translation>
    </message>
    <message>
        <source>The programmed finishing pass (f %1 mm/rev, vc %2 m/min) lies outside this window.</source>
        <translation>Der programmierte Schlichtschnitt (f %1 mm/U, vc %2 m/min) liegt außerhalb dieses Fensters.</translation>
    </message>
    <message>
        <source> (Valiño et al. 2008, %1)</source>
        <translation> (Valiño et al. 2008, %1)</translation>
    </message>
    <message>
        <source>size within %1–%2 mm</source>
        <translation>Maß zwischen %1 und %2 mm</translation>
    </message>
    <message>
        <source>%1 of %2 µm predicted against a zone of %3 µm</source>
        <translation>%1 von %2 µm vorhergesagt, bei einer Toleranzzone von %3 µm</translation>
    </message>
    <message>
        <source>6  Assumptions</source>
        <translation>6  Annahmen</translation>
    </message>
    <message>
        <source>What this prediction rests on, beyond the project&apos;s own values:</source>
        <translation>Worauf diese Vorhersage über die Werte des Projekts hinaus beruht:</translation>
    </message>
    <message>
        <source>Appendix A  Literature</source>
        <translation>Anhang A  Literatur</translation>
    </message>
    <message>
        <source>[1] G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos: Machining error predictive model in a CAPP system for turning: formulation and initial tests (2008). Used: eq. 2–8 (deviation), §III (spindle–chuck springs from a test bar), §V and Fig. 4 (tolerances), §VI (optimisation).</source>
        <translation>[1] G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos: Machining error predictive model in a CAPP system for turning: formulation and initial tests (2008). Verwendet: Gl. 2–8 (Abweichung), §III (Federn von Spindel und Futter aus einem Prüfstab), §V und Abb. 4 (Toleranzen), §VI (Optimierung).</translation>
    </message>
    <message>
        <source>[2] X. Li, R. Du: Analysis and compensation of workpiece errors in turning. Int. J. Prod. Res. 40(7) (2002). Used: eq. 15–20 (forces with the nose radius), §3.4 (compensation).</source>
        <translation>[2] X. Li, R. Du: Analysis and compensation of workpiece errors in turning. Int. J. Prod. Res. 40(7) (2002). Verwendet: Gl. 15–20 (Kräfte mit dem Eckenradius), §3.4 (Kompensation).</translation>
    </message>
    <message>
        <source>[3] O. Kienzle: Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und Werkzeugmaschinen. VDI-Z 94 (1952) 299–305. Used: the specific cutting force kc1.1 · h^-mc.</source>
        <translation>[3] O. Kienzle: Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und Werkzeugmaschinen. VDI-Z 94 (1952) 299–305. Verwendet: die spezifische Schnittkraft kc1.1 · h^-mc.</translation>
    </message>
    <message>
        <source>[4] G. R. Cowper: The shear coefficient in Timoshenko&apos;s beam theory. J. Appl. Mech. 33 (1966) 335–340. Used: the shear coefficient of solid and hollow round sections.</source>
        <translation>[4] G. R. Cowper: The shear coefficient in Timoshenko&apos;s beam theory. J. Appl. Mech. 33 (1966) 335–340. Verwendet: der Schubkorrekturfaktor von Voll- und Hohlkreisquerschnitten.</translation>
    </message>
    <message>
        <source>[5] ISO 286-1 and ISO 286-2: limits and fits (tolerance grades, fundamental deviations).</source>
        <translation>[5] ISO 286-1 und ISO 286-2: Grenzmaße und Passungen (Toleranzgrade, Grundabmaße).</translation>
    </message>
    <message>
        <source>[6] ISO 1101: geometrical tolerancing (form, orientation, location and run-out).</source>
        <translation>[6] ISO 1101: Geometrische Tolerierung (Form, Richtung, Ort und Lauf).</translation>
    </message>
    <message>
        <source>[7] ISO 3002-1: basic quantities in cutting (entering and trailing edge angles).</source>
        <translation>[7] ISO 3002-1: Grundbegriffe der Zerspanung (Einstell- und Nebeneinstellwinkel).</translation>
    </message>
    <message>
        <source>The equations as implemented, the corrections of printing errors and the validation against closed forms: docs/model.md of TolTurn.</source>
        <translation>Die Gleichungen wie umgesetzt, die Korrekturen von Druckfehlern und die Validierung gegen geschlossene Lösungen: docs/model.md von TolTurn.</translation>
    </message>
    <message>
        <source>Appendix B  Sources of the data</source>
        <translation>Anhang B  Quellen der Daten</translation>
    </message>
    <message>
        <source>Chuck stiffness range: %1</source>
        <translation>Steifigkeitsbereich des Futters: %1</translation>
    </message>
    <message>
        <source>Machine stiffness, measured: %1</source>
        <translation>Maschinensteifigkeit, gemessen: %1</translation>
    </message>
    <message>
        <source>Tool life: %1</source>
        <translation>Standzeit: %1</translation>
    </message>
    <message>
        <source>z from the held (right) end [mm]</source>
        <translation>z vom gespannten (rechten) Ende [mm]</translation>
    </message>
    <message>
        <source>Feed [mm/rev]</source>
        <translation>Vorschub [mm/U]</translation>
    </message>
    <message>
        <source>Limited by</source>
        <translation>Begrenzt durch</translation>
    </message>
    <message>
        <source>kept: %1 is not held at any feed of the range</source>
        <translation>beibehalten: %1 wird bei keinem Vorschub des Bereichs gehalten</translation>
    </message>
    <message>
        <source>[8] F. Čuš, U. Župerl: Control strategy for assuring constant surface finish by controlling cutting forces (University of Maribor, 2013). Used: eq. 1 (feed drive), §2 (20 ms constant-force loop with feed override); TolTurn&apos;s feed schedule holds the tolerances feature by feature.</source>
        <translation>[8] F. Čuš, U. Župerl: Control strategy for assuring constant surface finish by controlling cutting forces (Universität Maribor, 2013). Verwendet: Gl. 1 (Vorschubantrieb), §2 (Konstantkraftregelung im 20-ms-Takt mit Vorschub-Override); der Vorschubplan von TolTurn hält die Toleranzen Formelement für Formelement.</translation>
    </message>
    <message>
        <source>7  Assumptions</source>
        <translation>7  Annahmen</translation>
    </message>
    <message>
        <source>[9] E. Öztürk, E. Budak: 5-Eksen Frezelemede Kuvvet ve Şekil Hatalarının Modellenmesi (modelling the forces and form errors of 5-axis milling; in Turkish), Sabancı University. Used: eq. 1–11 (the forces of a ball-end mill at a lead and tilt), table 3 and §4 (the tool&apos;s deflection and the surface-normal error); the milled features&apos; equations as implemented: docs/milling.md.</source>
        <translation>[9] E. Öztürk, E. Budak: 5-Eksen Frezelemede Kuvvet ve Şekil Hatalarının Modellenmesi (Modellierung der Kräfte und Formabweichungen beim 5-Achs-Fräsen; auf Türkisch), Sabancı-Universität. Verwendet: Gl. 1–11 (die Kräfte eines Kugelkopffräsers bei einem Anstell- und Kippwinkel), Tabelle 3 und §4 (die Ausbiegung des Werkzeugs und die Abweichung entlang der Flächennormalen); die Gleichungen der gefrästen Formelemente in der Umsetzung: docs/milling.md.</translation>
    </message>
    <message>
        <source>6  Milled features</source>
        <translation>6  Gefräste Formelemente</translation>
    </message>
    <message>
        <source>%1 violated %2</source>
        <translation>%1 %2 verletzt</translation>
    </message>
    <message>
        <source>To meet it: %1</source>
        <translation>Um sie einzuhalten: %1</translation>
    </message>
    <message>
        <source>Finishing pass %1, turning insert (nose radius %2 mm): forces (%3) Fc %4 N, Ff %5 N, Fp %6 N; theoretical Ra %7 µm, Rz %8 µm.</source>
        <translation>Schlichtschnitt %1, Drehplatte (Eckenradius %2 mm): Kräfte (%3) Fc %4 N, Ff %5 N, Fp %6 N; theoretische Rauheit Ra %7 µm, Rz %8 µm.</translation>
    </message>
    <message>
        <source>Bores, boring bar %1 (nose radius %2 mm), same pass: forces Fc %3 N, Ff %4 N, Fp %5 N; theoretical Ra %6 µm, Rz %7 µm.</source>
        <translation>Bohrungen, Bohrstange %1 (Eckenradius %2 mm), derselbe Schnitt: Kräfte Fc %3 N, Ff %4 N, Fp %5 N; theoretische Rauheit Ra %6 µm, Rz %7 µm.</translation>
    </message>
    <message>
        <source>Feed schedule of the finishing pass (after Čuš and Župerl [8]): each feature at the largest feed of the range that holds its tolerances and the pass&apos;s limits; %1 s at the programmed %2 mm/rev, %3 s scheduled (%4 %). Programmed only on request (gcode --feed-schedule, the G-code tab).</source>
        <translation>Vorschubplan des Schlichtschnitts (nach Čuš und Župerl [8]): jedes Formelement mit dem größten Vorschub des Bereichs, der seine Toleranzen und die Grenzen des Schnitts hält; %1 s beim programmierten Vorschub %2 mm/U, %3 s nach Plan (%4 %). Nur auf Wunsch programmiert (gcode --feed-schedule, Reiter G-Code).</translation>
    </message>
    <message>
        <source>%1 min per part; finishing vc %2 m/min, f %3 mm/rev, ap %4 mm; </source>
        <translation>%1 min je Teil; Schlichten vc %2 m/min, f %3 mm/U, ap %4 mm; </translation>
    </message>
    <message numerus="yes">
        <source>%n roughing pass(es) at vc %1 m/min, f %2 mm/rev.</source>
        <translation>
            <numerusform>%n Schruppschnitt bei vc %1 m/min, f %2 mm/U.</numerusform>
            <numerusform>%n Schruppschnitte bei vc %1 m/min, f %2 mm/U.</numerusform>
        </translation>
    </message>
    <message>
        <source>no roughing: the finishing pass takes the whole stock.</source>
        <translation>kein Schruppen: Der Schlichtschnitt nimmt das ganze Aufmaß.</translation>
    </message>
    <message>
        <source>; predicted %1 mm</source>
        <translation>; vorhergesagt %1 mm</translation>
    </message>
</context>
<context>
    <name>RevolvedFaces</name>
    <message>
        <source>a plane not perpendicular to the axis (a flat or a side of a keyway)</source>
        <translation>eine Ebene, die nicht senkrecht zur Achse steht (eine Abflachung oder eine Flanke einer Passfedernut)</translation>
    </message>
    <message>
        <source>a cylinder parallel to the axis but off it (an eccentric or an off-centre hole)</source>
        <translation>ein Zylinder parallel zur Achse, aber außerhalb von ihr (ein Exzenter oder eine außermittige Bohrung)</translation>
    </message>
    <message>
        <source>a cylinder across the axis (a cross hole)</source>
        <translation>ein Zylinder quer zur Achse (eine Querbohrung)</translation>
    </message>
    <message>
        <source>a cone whose axis is not the part axis (a countersink of a cross hole)</source>
        <translation>ein Kegel, dessen Achse nicht die Teilachse ist (eine Senkung einer Querbohrung)</translation>
    </message>
    <message>
        <source>a torus whose axis is not the part axis</source>
        <translation>ein Torus, dessen Achse nicht die Teilachse ist</translation>
    </message>
    <message>
        <source>a sphere whose centre is off the axis</source>
        <translation>eine Kugel, deren Mittelpunkt nicht auf der Achse liegt</translation>
    </message>
    <message>
        <source>a free-form (B-spline) surface, such as a modelled thread or an engraving</source>
        <translation>eine Freiformfläche (B-Spline), etwa ein modelliertes Gewinde oder eine Gravur</translation>
    </message>
    <message>
        <source>a surface of revolution of a free-form curve</source>
        <translation>eine Rotationsfläche einer Freiformkurve</translation>
    </message>
    <message>
        <source>an extruded free-form surface</source>
        <translation>eine extrudierte Freiformfläche</translation>
    </message>
    <message>
        <source>a surface of a kind TolTurn does not turn (offset or other)</source>
        <translation>eine Fläche einer Art, die TolTurn nicht dreht (Offsetfläche oder andere)</translation>
    </message>
    <message>
        <source>a part of a turned surface that does not go round (the end wall of a keyway or a slot)</source>
        <translation>ein Abschnitt einer gedrehten Fläche, der nicht ganz umläuft (die Stirnwand einer Passfedernut oder einer Nut)</translation>
    </message>
    <message>
        <source>a plane</source>
        <translation>eine Ebene</translation>
    </message>
    <message>
        <source>a cylinder</source>
        <translation>ein Zylinder</translation>
    </message>
    <message>
        <source>a cone</source>
        <translation>ein Kegel</translation>
    </message>
    <message>
        <source>a sphere</source>
        <translation>eine Kugel</translation>
    </message>
    <message>
        <source>a torus</source>
        <translation>ein Torus</translation>
    </message>
    <message>
        <source>a torus about the part axis</source>
        <translation>ein Torus um die Teileachse</translation>
    </message>
    <message>
        <source>a cylinder, cone or face about the part axis</source>
        <translation>ein Zylinder, Kegel oder eine Planfläche um die Teileachse</translation>
    </message>
</context>
<context>
    <name>SetupPrediction</name>
    <message>
        <source>%1 (set-up %2 of %3, the %4 end held): </source>
        <translation>%1 (Aufspannung %2 von %3, Ende %4 gespannt): </translation>
    </message>
    <message>
        <source>%1. Without it: %2</source>
        <translation>%1. Ohne es: %2</translation>
    </message>
</context>
<context>
    <name>SetupSheet</name>
    <message>
        <source>cutting speed</source>
        <translation>Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>feed</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation>Schnitttiefe</translation>
    </message>
    <message>
        <source>tool overhang</source>
        <translation>Werkzeugauskragung</translation>
    </message>
    <message>
        <source>clamped length</source>
        <translation>Spannlänge</translation>
    </message>
    <message>
        <source>stock diameter</source>
        <translation>Rohteildurchmesser</translation>
    </message>
    <message>
        <source>chuck: %1 mm in the jaws</source>
        <translation>Futter: %1 mm in den Backen</translation>
    </message>
    <message>
        <source>centre and driver</source>
        <translation>Spitze und Mitnehmer</translation>
    </message>
    <message>
        <source>tailstock centre</source>
        <translation>Reitstockspitze</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>n [rpm]</source>
        <translation>n [1/min]</translation>
    </message>
    <message>
        <source>vc [m/min]</source>
        <translation>vc [m/min]</translation>
    </message>
    <message>
        <source>f [mm/rev]</source>
        <translation>f [mm/U]</translation>
    </message>
    <message>
        <source>ap [mm]</source>
        <translation>ap [mm]</translation>
    </message>
    <message>
        <source>Power [kW]</source>
        <translation>Leistung [kW]</translation>
    </message>
    <message>
        <source>Time [min]</source>
        <translation>Zeit [min]</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>total cutting</source>
        <translation>Schnittzeit gesamt</translation>
    </message>
    <message>
        <source>Program warning: %1</source>
        <translation>Programmwarnung: %1</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>pass %1</source>
        <translation>Schnitt %1</translation>
    </message>
    <message>
        <source>passes %1</source>
        <translation>Schnitte %1</translation>
    </message>
    <message>
        <source>collet: %1 mm held</source>
        <translation>Spannzange: %1 mm gespannt</translation>
    </message>
    <message numerus="yes">
        <source>Program %1 for %2, %n pass(es); spindle limit %3 rpm (%4). Checksum (SHA-256, first 16 digits) of the nominal program %5, of the compensated program %6: compare them with `tolturn-cli gcode` or the G-code tab before running.</source>
        <translation>
            <numerusform>Programm %1 für %2, %n Schnitt; Drehzahlbegrenzung %3 1/min (%4). Prüfsumme (SHA-256, erste 16 Stellen) des nominalen Programms %5, des kompensierten Programms %6: vor dem Abarbeiten mit `tolturn-cli gcode` oder dem G-Code-Reiter vergleichen.</numerusform>
            <numerusform>Programm %1 für %2, %n Schnitte; Drehzahlbegrenzung %3 1/min (%4). Prüfsumme (SHA-256, erste 16 Stellen) des nominalen Programms %5, des kompensierten Programms %6: vor dem Abarbeiten mit `tolturn-cli gcode` oder dem G-Code-Reiter vergleichen.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SolidCheck</name>
    <message>
        <source>the solid check was cancelled; the project is unchanged</source>
        <translation>die Prüfung mit dem Volumenmodell wurde abgebrochen; das Projekt ist unverändert</translation>
    </message>
    <message>
        <source>could not write the mesh script in %1</source>
        <translation>das Vernetzungsskript konnte nicht in %1 geschrieben werden</translation>
    </message>
    <message>
        <source>meshing with gmsh</source>
        <translation>Vernetzung mit gmsh</translation>
    </message>
    <message>
        <source>gmsh could not mesh the part with elements of %1 mm (exit code %2): %3</source>
        <translation>gmsh konnte das Teil nicht mit Elementen von %1 mm vernetzen (Exit-Code %2): %3</translation>
    </message>
    <message>
        <source>could not write the CalculiX input in %1</source>
        <translation>die CalculiX-Eingabedatei konnte nicht in %1 geschrieben werden</translation>
    </message>
    <message>
        <source>solving with CalculiX: load case %1 of %2</source>
        <translation>Lösen mit CalculiX: Lastfall %1 von %2</translation>
    </message>
    <message>
        <source>it wrote no results</source>
        <translation>es wurden keine Ergebnisse geschrieben</translation>
    </message>
    <message>
        <source>CalculiX failed (exit code %1): %2</source>
        <translation>CalculiX ist fehlgeschlagen (Exit-Code %1): %2</translation>
    </message>
    <message>
        <source>CalculiX moved the part by %1 mm, more than its length: the clamping does not hold the solid</source>
        <translation>CalculiX hat das Teil um %1 mm verschoben, mehr als seine Länge: die Einspannung hält das Volumenmodell nicht</translation>
    </message>
    <message>
        <source>The machine&apos;s supports are rigid in both models: the check is of the part&apos;s own deflection.</source>
        <translation>Die Abstützungen der Maschine sind in beiden Modellen starr: geprüft wird die Durchbiegung des Teils selbst.</translation>
    </message>
    <message>
        <source>Solid: quadratic tetrahedra (C3D10) of at most %1 mm; %2 nodes, %3 free degrees of freedom.</source>
        <translation>Volumenmodell: quadratische Tetraeder (C3D10) von höchstens %1 mm; %2 Knoten, %3 freie Freiheitsgrade.</translation>
    </message>
    <message>
        <source>The force is a uniform traction on a %1 mm square patch of the turned surface; the solid&apos;s deflection is the area mean of the displacement of its section under the load.</source>
        <translation>Die Kraft ist eine gleichmäßige Flächenlast auf einem quadratischen Feld von %1 mm der gedrehten Fläche; die Durchbiegung des Volumenmodells ist der Flächenmittelwert der Verschiebung seines Querschnitts unter der Last.</translation>
    </message>
    <message>
        <source>A centre holds the end face within 3.35 mm of the axis (DIN 332-1 form A, d2 = 6.7 mm), or 1.78 mm of a bore&apos;s edge.</source>
        <translation>Eine Spitze hält die Stirnfläche innerhalb von 3,35 mm um die Achse (DIN 332-1 Form A, d2 = 6,7 mm) oder innerhalb von 1,78 mm um die Kante einer Bohrung.</translation>
    </message>
    <message>
        <source>A chuck or collet holds the turned surface of its clamped length rigidly.</source>
        <translation>Ein Spannfutter oder eine Spannzange hält die gedrehte Fläche auf der Spannlänge starr.</translation>
    </message>
    <message>
        <source>The part is checked as finished: stock a later set-up removes is not in either model.</source>
        <translation>Das Teil wird im Fertigzustand geprüft: Material, das eine spätere Aufspannung abträgt, ist in keinem der beiden Modelle enthalten.</translation>
    </message>
    <message>
        <source>operation %1 does not exist; the project has %2</source>
        <translation>Aufspannung %1 existiert nicht; das Projekt hat %2</translation>
    </message>
    <message>
        <source>the mesh size must be a positive length in mm, not %1</source>
        <translation>die Netzgröße muss eine positive Länge in mm sein, nicht %1</translation>
    </message>
    <message>
        <source>could not make a temporary folder: %1</source>
        <translation>es konnte kein temporärer Ordner angelegt werden: %1</translation>
    </message>
    <message>
        <source>Files kept in %1 (TOLTURN_FE_KEEP).</source>
        <translation>Dateien in %1 aufbewahrt (TOLTURN_FE_KEEP).</translation>
    </message>
    <message>
        <source>writing the solid</source>
        <translation>Schreiben des Volumenmodells</translation>
    </message>
    <message>
        <source>setting up the load cases</source>
        <translation>Aufstellen der Lastfälle</translation>
    </message>
    <message>
        <source>no turned cylinder or cone between the supports is long enough to load</source>
        <translation>kein gedrehter Zylinder oder Kegel zwischen den Abstützungen ist lang genug, um ihn zu belasten</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <source>The beam carries its corrections from solid FE (the root in the jaws, a hinge at each shoulder); Timoshenko is the beam without them (docs/solid-fe.md).</source>
        <translation>Der Balken trägt seine Korrekturen aus Volumen-FE (die Einspannung in den Backen, ein Gelenk an jedem Absatz); Timoshenko ist der Balken ohne sie (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>The beam is plain Timoshenko, without its corrections.</source>
        <translation>Der Balken ist reiner Timoshenko, ohne seine Korrekturen.</translation>
    </message>
</context>
<context>
    <name>SpindleCalibration</name>
    <message>
        <source>the %1 fit gives %2 = %3, which is not a spring (it must be above zero): the measured deviation does not grow from the chuck as a spindle–chuck held by springs would. Check the measurement, the forces, Lc and that the bar is held in the chuck only</source>
        <translation>die Anpassung (%1) ergibt %2 = %3, das ist keine Feder (der Wert muss über null liegen): die gemessene Abweichung wächst nicht vom Futter weg, wie es bei einer von Federn gehaltenen Spindel–Futter-Einheit wäre. Prüfen Sie die Messung, die Kräfte, Lc und dass der Stab nur im Futter gespannt ist</translation>
    </message>
    <message>
        <source>the test bar must be held in the chuck only (Valiño et al. 2008 §III); a centre would carry part of the load</source>
        <translation>der Prüfstab muss nur im Futter gespannt sein (Valiño et al. 2008 §III); eine Spitze würde einen Teil der Last tragen</translation>
    </message>
    <message>
        <source>Lc, the distance of the spindle bearing behind the chuck face, must be above zero, but is %1 mm</source>
        <translation>Lc, der Abstand des Spindellagers hinter der Futterfläche, muss über null liegen, ist aber %1 mm</translation>
    </message>
    <message>
        <source>the fit of a z² + b z + c needs points at three or more positions z, but there are %1</source>
        <translation>die Anpassung von a z² + b z + c braucht Punkte an drei oder mehr Stellen z, es sind aber %1</translation>
    </message>
    <message>
        <source>z = %1 mm is not on the turned outer surface of the bar</source>
        <translation>z = %1 mm liegt nicht auf der gedrehten Außenfläche des Stabs</translation>
    </message>
    <message>
        <source>z = %1 mm lies on Ø%2 mm, but the first point on Ø%3 mm: the fit needs the bar&apos;s points on one diameter</source>
        <translation>z = %1 mm liegt auf Ø%2 mm, der erste Punkt aber auf Ø%3 mm: die Anpassung braucht die Punkte des Stabs auf einem Durchmesser</translation>
    </message>
    <message>
        <source>the radial force must be above zero, but is %1 N</source>
        <translation>die Radialkraft muss über null liegen, ist aber %1 N</translation>
    </message>
    <message>
        <source>the bar&apos;s own bending and the toolpost make %1 % of the deviation measured at z = %2 mm: a stiffer (shorter, thicker) bar gives a surer fit</source>
        <translation>die Biegung des Stabs selbst und der Werkzeughalter machen %1 % der bei z = %2 mm gemessenen Abweichung aus: ein steiferer (kürzerer, dickerer) Stab gibt eine sicherere Anpassung</translation>
    </message>
    <message>
        <source>radial</source>
        <translation>radial</translation>
    </message>
    <message>
        <source>tangential</source>
        <translation>tangential</translation>
    </message>
    <message>
        <source>tangential_um is given at %1 positions z; the fit needs three or more: the tangential springs are not fitted</source>
        <translation>tangential_um ist an %1 Positionen z angegeben; die Anpassung braucht drei oder mehr: die tangentialen Federn werden nicht angepasst</translation>
    </message>
    <message>
        <source>the tangential force is %1 N: the tangential springs are not fitted</source>
        <translation>die Tangentialkraft ist %1 N: die tangentialen Federn werden nicht angepasst</translation>
    </message>
    <message>
        <source>the tangential springs were fitted for Lc = %1 mm and do not hold at Lc = %2 mm: removed; measure the tangential deviation to fit them again</source>
        <translation>die tangentialen Federn wurden für Lc = %1 mm angepasst und gelten nicht bei Lc = %2 mm: entfernt; messen Sie die tangentiale Abweichung, um sie neu anzupassen</translation>
    </message>
    <message>
        <source>three positions z fit a z² + b z + c exactly: the RMS residual of 0 says nothing of the measurement&apos;s scatter, which goes into the springs whole; measure at four or more</source>
        <translation>drei Positionen z werden von a z² + b z + c exakt getroffen: der RMS-Rest von 0 sagt nichts über die Streuung der Messung, die ganz in die Federn eingeht; messen Sie an vier oder mehr</translation>
    </message>
</context>
<context>
    <name>StepExport</name>
    <message>
        <source>cannot write &apos;%1&apos;: the profile has errors, first %2</source>
        <translation>„%1“ kann nicht geschrieben werden: das Profil enthält Fehler, der erste: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>OpenCascade could not write the solid to &apos;%1&apos;</source>
        <translation>OpenCascade konnte den Körper nicht in „%1“ schreiben</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: renaming the temporary file failed</source>
        <translation>„%1“ kann nicht gespeichert werden: das Umbenennen der temporären Datei ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>OpenCascade failed while writing &apos;%1&apos;: %2</source>
        <translation>Fehler in OpenCascade beim Schreiben von „%1“: %2</translation>
    </message>
    <message>
        <source>writing &apos;%1&apos; failed: %2</source>
        <translation>das Schreiben von „%1“ ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>cannot set the permissions of &apos;%1&apos;: %2</source>
        <translation>die Zugriffsrechte von &apos;%1&apos; können nicht gesetzt werden: %2</translation>
    </message>
</context>
<context>
    <name>StepImport</name>
    <message>
        <source>&apos;%1&apos; is not a STEP file: it does not begin with &apos;ISO-10303-21;&apos; (ISO 10303-21)</source>
        <translation>„%1“ ist keine STEP-Datei: sie beginnt nicht mit „ISO-10303-21;“ (ISO 10303-21)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is truncated: a STEP file ends with &apos;END-ISO-10303-21;&apos;, which is missing</source>
        <translation>„%1“ ist unvollständig: eine STEP-Datei endet mit „END-ISO-10303-21;“, was hier fehlt</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an IGES file: its first line is not a Start section record (IGES 5.3)</source>
        <translation>„%1“ ist keine IGES-Datei: ihre erste Zeile ist kein Datensatz des Start-Abschnitts (IGES 5.3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is truncated: an IGES file ends with a Terminate section record, which is missing</source>
        <translation>„%1“ ist unvollständig: eine IGES-Datei endet mit einem Datensatz des Terminate-Abschnitts, der hier fehlt</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not exist</source>
        <translation>„%1“ existiert nicht</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a file</source>
        <translation>„%1“ ist keine Datei</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is empty</source>
        <translation>„%1“ ist leer</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>OpenCascade cannot parse &apos;%1&apos; as a STEP file (ISO 10303-21)</source>
        <translation>OpenCascade kann „%1“ nicht als STEP-Datei (ISO 10303-21) einlesen</translation>
    </message>
    <message>
        <source>OpenCascade cannot parse &apos;%1&apos; as an IGES file</source>
        <translation>OpenCascade kann „%1“ nicht als IGES-Datei einlesen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no shape that OpenCascade can transfer (no solid, shell or face)</source>
        <translation>„%1“ enthält keine Geometrie, die OpenCascade übernehmen kann (keinen Körper, keine Schale und keine Fläche)</translation>
    </message>
    <message>
        <source>there is no %1 %2: the file has %3 (numbered from 0)</source>
        <translation>%1 %2 gibt es nicht: die Datei enthält %3 (nummeriert ab 0)</translation>
    </message>
    <message>
        <source>body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>the file holds %1 bodies; body %2 (%3 mm³) is imported, choose another with the solid option</source>
        <translation>die Datei enthält %1 Körper; Körper %2 (%3 mm³) wird importiert, wählen Sie mit der Option solid einen anderen</translation>
    </message>
    <message>
        <source>the body in &apos;%1&apos; has no cylindrical, conical or toroidal face: it is not a turned part</source>
        <translation>der Körper in „%1“ hat keine zylindrische, kegelige oder torusförmige Fläche: er ist kein Drehteil</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>the body has revolved faces about %1 different axes; axis %2 (%3 mm² of revolved faces) is the part axis, choose another with the axis option</source>
        <translation>der Körper hat Rotationsflächen um %1 verschiedene Achsen; Achse %2 (%3 mm² Rotationsflächen) ist die Teilachse, wählen Sie mit der Option axis eine andere</translation>
    </message>
    <message>
        <source>face %1 is %2, from z = %3 mm to z = %4 mm; it is not rotationally symmetric about the part axis and is left out of the profile</source>
        <translation>Fläche %1 ist %2, von z = %3 mm bis z = %4 mm; sie ist nicht rotationssymmetrisch zur Teilachse und wird im Profil weggelassen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a STEP or IGES file: TolTurn reads files ending in .step, .stp, .iges or .igs</source>
        <translation>„%1“ ist keine STEP- oder IGES-Datei: TolTurn liest Dateien mit den Endungen .step, .stp, .iges oder .igs</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no solid, shell or face</source>
        <translation>„%1“ enthält keinen Körper, keine Schale und keine Fläche</translation>
    </message>
    <message>
        <source>reading &apos;%1&apos; failed: %2</source>
        <translation>das Lesen von „%1“ ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: the number &apos;%3&apos; is beyond the largest real (about 1.8e308)</source>
        <translation>&apos;%1&apos;, Zeile %2: Die Zahl &apos;%3&apos; liegt jenseits der größten reellen Zahl (etwa 1,8e308)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2</source>
        <translation>&apos;%1&apos; ist kein widerspruchsfreies Modell: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; could not be read: OpenCascade stopped on an invalid model (%2); check the file in the CAD system that wrote it</source>
        <translation>&apos;%1&apos; konnte nicht gelesen werden: OpenCascade hielt bei einem ungültigen Modell an (%2); prüfen Sie die Datei in dem CAD-System, das sie geschrieben hat</translation>
    </message>
    <message>
        <source>face %1 is written as a B-spline surface and was read as %2, which it is within 0.001 mm</source>
        <translation>Fläche %1 ist als B-Spline-Fläche geschrieben und wurde als %2 gelesen, was sie bis auf 0,001 mm ist</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2 refers to itself</source>
        <translation>„%1“ ist kein konsistentes Modell: %2 verweist auf sich selbst</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2 refers to %3, which leads back to %2 (a cycle of references)</source>
        <translation>„%1“ ist kein konsistentes Modell: %2 verweist auf %3, das zurück zu %2 führt (ein Verweiszyklus)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; nests its entities %2 deep at %3, more than the %4 any CAD model needs</source>
        <translation>„%1“ verschachtelt seine Entitäten bei %3 %2 Ebenen tief, mehr als die %4, die ein CAD-Modell braucht</translation>
    </message>
    <message>
        <source>&apos;%1&apos; could not be read: OpenCascade failed on it (%2); check the file in the CAD system that wrote it</source>
        <translation>„%1“ konnte nicht gelesen werden: OpenCascade scheiterte daran (%2); prüfen Sie die Datei im CAD-System, das sie geschrieben hat</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <source>faces %1</source>
        <translation>Flächen %1</translation>
    </message>
    <message>
        <source>the flat of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a tool, conditions, cutting coefficients and a tolerance to evaluate it</source>
        <translation>die Abflachung aus %1, von z = %2 mm bis z = %3 mm, wurde zum gefrästen Formelement %4; geben Sie ihm Werkzeug, Schnittbedingungen, Schnittkraftkoeffizienten und eine Toleranz, um es auszuwerten</translation>
    </message>
    <message>
        <source>the keyway of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a tool, conditions, cutting coefficients and a tolerance to evaluate it</source>
        <translation>die Passfedernut aus %1, von z = %2 mm bis z = %3 mm, wurde zum gefrästen Formelement %4; geben Sie ihm Werkzeug, Schnittbedingungen, Schnittkraftkoeffizienten und eine Toleranz, um es auszuwerten</translation>
    </message>
    <message>
        <source>&apos;%1&apos; was not read: OpenCascade would not transfer shapes in millimetres (xstep.cascade.unit)</source>
        <translation>&apos;%1&apos; wurde nicht gelesen: OpenCascade übertrug die Formen nicht in Millimetern (xstep.cascade.unit)</translation>
    </message>
</context>
<context>
    <name>StiffnessCommand</name>
    <message>
        <source>  %1: k1 = %2 N/mm, k2 = %3 N·mm/rad, k3 = %4 N·mm/rad; RMS residual %5 µm over %6 points</source>
        <translation>  %1: k1 = %2 N/mm, k2 = %3 N·mm/rad, k3 = %4 N·mm/rad; RMS-Restfehler %5 µm über %6 Punkte</translation>
    </message>
    <message>
        <source>Spindle–chuck springs from the test bar (Valiño et al. 2008 §III): Lc = %1 mm, Ø%2 mm, F_r = %3 N, F_t = %4 N, F_a = %5 N</source>
        <translation>Federn der Spindel–Futter-Einheit aus dem Prüfstab (Valiño et al. 2008 §III): Lc = %1 mm, Ø%2 mm, F_r = %3 N, F_t = %4 N, F_a = %5 N</translation>
    </message>
    <message>
        <source>radial</source>
        <translation>radial</translation>
    </message>
    <message>
        <source>tangential</source>
        <translation>tangential</translation>
    </message>
    <message>
        <source>  tangential: not measured (no tangential_um column)</source>
        <translation>  tangential: nicht gemessen (keine Spalte tangential_um)</translation>
    </message>
    <message>
        <source>The bar&apos;s own bending and the toolpost, subtracted before the fit: %1 % of the deviation measured farthest from the chuck.</source>
        <translation>Biegung des Stabs und Werkzeughalter, vor der Anpassung abgezogen: %1 % der am weitesten vom Futter gemessenen Abweichung.</translation>
    </message>
    <message>
        <source>Test bar fit (Valiño et al. 2008 §III), tolturn-cli calibrate-stiffness, %1, %2: %3 points, RMS residual %4 µm</source>
        <translation>Prüfstab-Anpassung (Valiño et al. 2008 §III), tolturn-cli calibrate-stiffness, %1, %2: %3 Punkte, RMS-Restfehler %4 µm</translation>
    </message>
    <message>
        <source>Fit the spindle–chuck springs k1, k2, k3 (radial, and tangential where measured) to the measured deviation of a test bar turned in the chuck (Valiño et al. 2008 §III); --write stores them in the test bar&apos;s project, --into in another project on the same machine.</source>
        <translation>Die Federn k1, k2, k3 der Spindel–Futter-Einheit (radial, und tangential, wo gemessen) an die gemessene Abweichung eines im Futter gedrehten Prüfstabs anpassen (Valiño et al. 2008 §III); --write speichert sie im Projekt des Prüfstabs, --into in einem anderen Projekt auf derselben Maschine.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Das Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Lc: distance of the front spindle bearing behind the chuck face, in mm (default: the project&apos;s characterisation).</source>
        <translation>Lc: Abstand des vorderen Spindellagers hinter der Futterfläche in mm (Vorgabe: die Charakterisierung des Projekts).</translation>
    </message>
    <message>
        <source>Measured forces of the test cut in newtons, radial,tangential,axial (default: the project&apos;s force model).</source>
        <translation>Gemessene Kräfte des Prüfschnitts in Newton, radial,tangential,axial (Vorgabe: das Kraftmodell des Projekts).</translation>
    </message>
    <message>
        <source>Store the springs in the test bar&apos;s project and save it.</source>
        <translation>Die Federn im Projekt des Prüfstabs speichern und es sichern.</translation>
    </message>
    <message>
        <source>Store the springs in this project instead and save it.</source>
        <translation>Die Federn stattdessen in diesem Projekt speichern und es sichern.</translation>
    </message>
    <message>
        <source>Project of the test bar as cut: chuck only, its part, tool, material and pass.</source>
        <translation>Projekt des Prüfstabs wie gedreht: nur Futter, sein Teil, Werkzeug, Werkstoff und Schnitt.</translation>
    </message>
    <message>
        <source>CSV of the measured bar: z_mm,radial_um[,tangential_um].</source>
        <translation>CSV des gemessenen Stabs: z_mm,radial_um[,tangential_um].</translation>
    </message>
    <message>
        <source>give a test bar project and a measurements file, and --write or --into, not both</source>
        <translation>ein Prüfstab-Projekt und eine Messdatei angeben, und --write oder --into, nicht beides</translation>
    </message>
    <message>
        <source>--pivot takes a length in mm, not &quot;%1&quot;</source>
        <translation>--pivot erwartet eine Länge in mm, nicht &quot;%1&quot;</translation>
    </message>
    <message>
        <source>wrote %1: spindle–chuck springs</source>
        <translation>%1 geschrieben: Federn der Spindel–Futter-Einheit</translation>
    </message>
    <message>
        <source>--load takes three numbers in newtons, radial,tangential,axial, each at most 1e6, not &quot;%1&quot;</source>
        <translation>--load nimmt drei Zahlen in Newton, radial,tangential,axial, jede höchstens 1e6, nicht &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 is planned for machine &quot;%2&quot;, but the test bar was cut on &quot;%3&quot;: its springs are that machine&apos;s; nothing written</source>
        <translation>%1 ist für die Maschine „%2“ geplant, der Prüfstab wurde aber auf „%3“ gedreht: seine Federn sind die jener Maschine; nichts geschrieben</translation>
    </message>
    <message>
        <source>  tangential: not fitted (the warning above says why)</source>
        <translation>  tangential: nicht angepasst (die Warnung oben sagt, warum)</translation>
    </message>
    <message>
        <source>Lc, the distance of the spindle bearing behind the chuck face, is not given: give it with --pivot MM, or in the project&apos;s characterisation</source>
        <translation>Lc, der Abstand des Spindellagers hinter der Futterfläche, ist nicht angegeben: mit --pivot MM oder in der Charakterisierung des Projekts angeben</translation>
    </message>
</context>
<context>
    <name>TableCopy</name>
    <message>
        <source>Copy Table as CSV</source>
        <translation>Tabelle als CSV kopieren</translation>
    </message>
</context>
<context>
    <name>TetMeshText</name>
    <message>
        <source>line %1 of the mesh is not a list of numbers: &quot;%2&quot;</source>
        <translation>Zeile %1 des Netzes ist keine Liste von Zahlen: „%2“</translation>
    </message>
    <message>
        <source>the mesh has no quadratic tetrahedra (C3D10)</source>
        <translation>das Netz enthält keine quadratischen Tetraeder (C3D10)</translation>
    </message>
    <message>
        <source>an element of the mesh uses node %1, which it does not define</source>
        <translation>ein Element des Netzes verwendet Knoten %1, den das Netz nicht definiert</translation>
    </message>
</context>
<context>
    <name>ToleranceVerdicts</name>
    <message>
        <source>feature %1 is not cut in this set-up (it lies in the chuck jaws or outside the supported length), so no deviation is predicted for it</source>
        <translation>Formelement %1 wird in dieser Aufspannung nicht bearbeitet (es liegt in den Spannbacken oder außerhalb der abgestützten Länge), daher wird dafür keine Abweichung vorhergesagt</translation>
    </message>
    <message>
        <source>the limits of %1 at %2 mm cannot be formed</source>
        <translation>die Grenzabmaße von %1 bei %2 mm können nicht gebildet werden</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 13: D&apos;_Md &lt;= Dn + dDu and D&apos;_md &gt;= Dn + dDl</source>
        <translation>Fig. 4b, eq. 13: D&apos;_Md &lt;= Dn + dDu und D&apos;_md &gt;= Dn + dDl</translation>
    </message>
    <message>
        <source>Fig. 4b: eq. 13 fails as programmed, eq. 15 holds: 2|delta_TMd - delta_Tmd| &lt;= t</source>
        <translation>Fig. 4b: eq. 13 wie programmiert nicht erfüllt, eq. 15 erfüllt: 2|delta_TMd - delta_Tmd| &lt;= t</translation>
    </message>
    <message>
        <source>a constant tool offset of %1 µm on the diameter centres the size in its tolerance</source>
        <translation>eine konstante Werkzeugkorrektur von %1 µm auf den Durchmesser zentriert das Maß in seiner Toleranz</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| &gt; t</source>
        <translation>Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| &gt; t</translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation>im Profil gibt es kein Formelement „%1“</translation>
    </message>
    <message>
        <source>Perpendicularity of an axis to a face depends on how the part is aligned in the lathe; the axis recovers elastically after cutting, so the cutting-force deflection does not decide it (Valiño et al. 2008 §V.G.2).</source>
        <translation>Die Rechtwinkligkeit einer Achse zu einer Planfläche hängt davon ab, wie das Teil in der Drehmaschine ausgerichtet ist; die Achse federt nach dem Schnitt elastisch zurück, daher entscheidet die Verformung unter der Schnittkraft nicht darüber (Valiño et al. 2008 §V.G.2).</translation>
    </message>
    <message>
        <source>Coaxiality limits how far parts of the axis lie apart; the axis recovers elastically after cutting, so the error comes from set-up and alignment, not from the cutting-force deflection (Valiño et al. 2008 §V.H).</source>
        <translation>Die Koaxialität begrenzt, wie weit Teile der Achse auseinanderliegen; die Achse federt nach dem Schnitt elastisch zurück, daher stammt der Fehler aus Aufspannung und Ausrichtung, nicht aus der Verformung unter der Schnittkraft (Valiño et al. 2008 §V.H).</translation>
    </message>
    <message>
        <source>The deflection under the cutting force is symmetrical about the axis of rotation and leaves no circular run-out; that comes from clamping deformation or misalignment (Valiño et al. 2008 §V.I).</source>
        <translation>Die Verformung unter der Schnittkraft ist symmetrisch zur Drehachse und verursacht keinen Rundlauffehler; dieser entsteht durch Spannverformung oder Fehlausrichtung (Valiño et al. 2008 §V.I).</translation>
    </message>
    <message>
        <source>passes as programmed</source>
        <translation>erfüllt wie programmiert</translation>
    </message>
    <message>
        <source>passes after a constant offset</source>
        <translation>erfüllt nach konstanter Korrektur</translation>
    </message>
    <message>
        <source>needs a profile correction</source>
        <translation>erfordert eine Konturkorrektur</translation>
    </message>
    <message>
        <source>not predicted by this model</source>
        <translation>von diesem Modell nicht vorhergesagt</translation>
    </message>
    <message>
        <source>cannot be evaluated</source>
        <translation>nicht auswertbar</translation>
    </message>
    <message>
        <source>the predicted deviation of feature %1 is not finite, so nothing can be said of it</source>
        <translation>die vorhergesagte Abweichung von Element %1 ist nicht endlich, daher lässt sich nichts darüber sagen</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 15 holds for this tolerance, but the form does not fit the %1 µm zone that all of the feature&apos;s size tolerances allow</source>
        <translation>Fig. 4b, Gl. 15 gilt für diese Toleranz, aber die Form passt nicht in die %1 µm breite Zone, die alle Maßtoleranzen des Formelements zulassen</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with datums: a delta_n lies outside ±t/2 as programmed; a constant radial offset brings all within</source>
        <translation>ISO 1101 Flächenform, mit Bezügen: ein delta_n liegt wie programmiert außerhalb ±t/2; eine konstante radiale Korrektur bringt alle hinein</translation>
    </message>
    <message>
        <source>a constant offset of %1 µm on the diameter (%2 µm normal to the surface) centres it in the zone</source>
        <translation>eine konstante Korrektur von %1 µm am Durchmesser (%2 µm normal zur Fläche) zentriert es in der Zone</translation>
    </message>
    <message>
        <source>a constant offset of %1 µm on the diameter brings every delta_n within ±t/2</source>
        <translation>eine konstante Korrektur von %1 µm am Durchmesser bringt jedes delta_n in ±t/2</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with datums: no constant offset brings every delta_n within ±t/2</source>
        <translation>ISO 1101 Flächenform, mit Bezügen: keine konstante Korrektur bringt jedes delta_n in ±t/2</translation>
    </message>
    <message>
        <source>a constant tool offset of %1 µm on the diameter centres the size in the %2 µm zone that all of the feature&apos;s size tolerances allow</source>
        <translation>eine konstante Werkzeugkorrektur von %1 µm auf den Durchmesser zentriert das Maß in der %2 µm breiten Zone, die alle Maßtoleranzen des Formelements zulassen</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with a datum that locates it along the axis: every delta_n within ±t/2</source>
        <translation>ISO 1101 Flächenform, mit einem Bezug, der sie längs der Achse festlegt: jedes delta_n innerhalb ±t/2</translation>
    </message>
    <message>
        <source>%1: %2 &lt;= t</source>
        <translation>%1: %2 &lt;= t</translation>
    </message>
    <message>
        <source>%1: %2 &gt; t</source>
        <translation>%1: %2 &gt; t</translation>
    </message>
    <message>
        <source>Fig. 4a, eq. 11–12</source>
        <translation>Fig. 4a, eq. 11–12</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, no datum (the zone floats along the axis)</source>
        <translation>ISO 1101 Flächenform, ohne Bezug (die Zone schwimmt längs der Achse)</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile to a datum axis only (the zone may slide along it)</source>
        <translation>ISO 1101 Flächenform, nur zu einer Bezugsachse (die Zone darf längs ihr gleiten)</translation>
    </message>
    <message>
        <source>Fig. 4c, eq. 16</source>
        <translation>Fig. 4c, eq. 16</translation>
    </message>
    <message>
        <source>Fig. 4f, eq. 23</source>
        <translation>Fig. 4f, eq. 23</translation>
    </message>
    <message>
        <source>Fig. 4i, §V.J (eq. 16 and 24)</source>
        <translation>Fig. 4i, §V.J (eq. 16 und 24)</translation>
    </message>
    <message>
        <source>Fig. 4g, eq. 24 (face to the datum axis)</source>
        <translation>Fig. 4g, eq. 24 (Planfläche zur Bezugsachse)</translation>
    </message>
    <message>
        <source>Fig. 4d, eq. 19</source>
        <translation>Fig. 4d, eq. 19</translation>
    </message>
    <message>
        <source>Fig. 4h, §V.J (eq. 19)</source>
        <translation>Fig. 4h, §V.J (eq. 19)</translation>
    </message>
    <message>
        <source>2 min over dz of max |delta_n - dz n_z|</source>
        <translation>2 min über dz von max |delta_n - dz n_z|</translation>
    </message>
</context>
<context>
    <name>Toolpath</name>
    <message>
        <source>left centre</source>
        <translation>linke Spitze</translation>
    </message>
    <message>
        <source>chuck face</source>
        <translation>Futterplanfläche</translation>
    </message>
    <message>
        <source>%1 reaches within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): it is not turned there.</source>
        <translation>%1 reicht bis auf %2 mm an die %3 heran, wohin das Werkzeug nicht fährt (es hält %4 mm Abstand): dort wird es nicht gedreht.</translation>
    </message>
    <message>
        <source>%1 reach within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): they are not turned there.</source>
        <translation>%1 reichen bis auf %2 mm an die %3 heran, wohin das Werkzeug nicht fährt (es hält %4 mm Abstand): dort werden sie nicht gedreht.</translation>
    </message>
    <message>
        <source>Turn that end with the part turned end for end.</source>
        <translation>Drehen Sie dieses Ende mit umgedrehtem Teil.</translation>
    </message>
    <message>
        <source>Grip the part shorter, or turn that end in another set-up.</source>
        <translation>Spannen Sie das Teil kürzer oder drehen Sie dieses Ende in einer weiteren Aufspannung.</translation>
    </message>
    <message>
        <source>%1 is narrower or tighter than the nose radius %2 mm: the nose cannot follow it and leaves it rounded.</source>
        <translation>%1 ist enger als der Eckenradius %2 mm: die Schneidenecke kann nicht folgen und lässt es verrundet.</translation>
    </message>
    <message>
        <source>The planned roughing leaves up to %1 mm more than the finishing allowance of %2 mm: the finishing pass would cut it.</source>
        <translation>Das geplante Schruppen lässt bis zu %1 mm mehr stehen als das Schlichtaufmaß von %2 mm: der Schlichtschnitt müsste es abnehmen.</translation>
    </message>
    <message>
        <source>The trailing edge angle of the tool is not known (holder entering angle and insert shape): falling contours are not checked.</source>
        <translation>Der Nebeneinstellwinkel des Werkzeugs ist nicht bekannt (Einstellwinkel des Halters und Plattenform): abfallende Konturen werden nicht geprüft.</translation>
    </message>
    <message>
        <source>The right end face is held by a centre and is not faced: it is faced and centred before the part is set up.</source>
        <translation>Die rechte Stirnfläche sitzt auf einer Spitze und wird nicht plangedreht: sie wird vor dem Aufspannen plangedreht und zentriert.</translation>
    </message>
    <message>
        <source>The tool stops %1 mm short of the %2; the stock there is not turned.</source>
        <translation>Das Werkzeug hält %1 mm vor %2 an; das Rohmaterial dort wird nicht gedreht.</translation>
    </message>
    <message>
        <source>left centre and driver</source>
        <translation>der linken Spitze und dem Mitnehmer</translation>
    </message>
    <message>
        <source>chuck jaws</source>
        <translation>den Spannbacken</translation>
    </message>
    <message>
        <source>No roughing pass is planned: the finishing pass would cut up to %1 mm more than its depth of cut.</source>
        <translation>Kein Schruppschnitt geplant: der Schlichtschnitt müsste bis zu %1 mm mehr als seine Schnitttiefe abnehmen.</translation>
    </message>
    <message>
        <source>%1 turns from the free end to z = %2 mm (from the held end); the rest of the outer contour is another operation&apos;s.</source>
        <translation>%1 dreht vom freien Ende bis z = %2 mm (vom gespannten Ende aus); der Rest der Außenkontur gehört zu einer anderen Aufspannung.</translation>
    </message>
    <message>
        <source>%1 is tighter than the nose radius %2 mm: it is programmed as the sharp corner it rounds (a control&apos;s compensation cannot follow a concave arc tighter than the nose), and the nose leaves it rounded to %2 mm.</source>
        <translation>%1 ist enger als der Eckenradius %2 mm: programmiert wird die scharfe Ecke, die der Radius verrundet (die Schneidenradiuskorrektur einer Steuerung kann einem konkaven Bogen, der enger als die Schneidenecke ist, nicht folgen), und die Schneidenecke hinterlässt dort eine Rundung mit %2 mm.</translation>
    </message>
    <message>
        <source>collet</source>
        <translation>Spannzange</translation>
    </message>
    <message>
        <source>%1: the recess of an undercut under its shoulder is not in this program (it turns the face down to the recess and the floor up to it): cut the recess with an undercut or grooving insert in a program of its own.</source>
        <translation>%1: Die Aussparung eines Freistichs unter seiner Schulter ist nicht in diesem Programm (es dreht die Planfläche bis zur Aussparung und den Grund bis an sie heran): die Aussparung mit einer Freistich- oder Einstechplatte in einem eigenen Programm schneiden.</translation>
    </message>
    <message>
        <source>%1: goes back along z (an undercut) without a face and a floor beside it: the program follows it, but only an insert that fits under the overhang can cut it; the insert&apos;s outline is not checked.</source>
        <translation>%1: läuft entlang z zurück (eine Hinterschneidung) ohne Planfläche und Grund daneben: das Programm folgt ihr, aber nur eine Platte, die unter den Überhang passt, kann sie schneiden; die Umrisslinie der Platte wird nicht geprüft.</translation>
    </message>
    <message>
        <source>No roughing pass is planned: the finishing pass would bore up to %1 mm more than its depth of cut from the pilot hole.</source>
        <translation>Kein Schruppschnitt ist geplant: Der Schlichtschnitt würde von der Vorbohrung aus bis zu %1 mm mehr als seine Schnitttiefe ausbohren.</translation>
    </message>
    <message>
        <source>The bore needs more than %1 roughing levels at the planned depths of cut: the program stops there.</source>
        <translation>Die Bohrung braucht bei den geplanten Schnitttiefen mehr als %1 Schruppebenen: Das Programm endet dort.</translation>
    </message>
    <message>
        <source>The boring levels leave up to %1 mm more than the finishing allowance of %2 mm: the finishing pass would cut it.</source>
        <translation>Die Bohrebenen lassen bis zu %1 mm mehr als das Schlichtaufmaß von %2 mm stehen: Der Schlichtschnitt würde es abtragen.</translation>
    </message>
    <message>
        <source>The trailing edge angle of the boring bar is not known (bar entering angle and insert shape): falling contours of the bore are not checked.</source>
        <translation>Der Nebenschneidenwinkel der Bohrstange ist nicht bekannt (Einstellwinkel der Stange und Plattenform): Fallende Konturen der Bohrung werden nicht geprüft.</translation>
    </message>
    <message>
        <source>Boring bar %1 reaches z = %2 mm with its overhang of %3 mm: the bore from z = %4 mm to there is not bored. Set a longer overhang.</source>
        <translation>Bohrstange %1 reicht mit ihrer Auskraglänge von %3 mm bis z = %2 mm: Die Bohrung von z = %4 mm bis dorthin wird nicht gebohrt. Stellen Sie eine größere Auskraglänge ein.</translation>
    </message>
    <message>
        <source>The pilot hole is not given (Set-up dock, Boring bar): the bore is taken as roughed to Ø%1 mm, its finishing allowance, before this program, and only its finishing pass is programmed.</source>
        <translation>Die Vorbohrung ist nicht angegeben (Dock Aufspannung, Bohrstange): Die Bohrung gilt als vor diesem Programm auf Ø%1 mm, ihr Schlichtaufmaß, vorgeschruppt, und nur ihr Schlichtschnitt wird programmiert.</translation>
    </message>
    <message>
        <source>The pilot hole Ø%1 mm is wider than the bore less its finishing allowance (Ø%2 mm): the finishing pass cuts less than its depth of cut.</source>
        <translation>Die Vorbohrung Ø%1 mm ist größer als die Bohrung abzüglich ihres Schlichtaufmaßes (Ø%2 mm): Der Schlichtschnitt schneidet weniger als seine Schnitttiefe.</translation>
    </message>
    <message>
        <source>Boring bar %1 (Ø%2 mm, edge %3 mm from its axis) does not fit in the Ø%4 mm hole it enters: it needs a hole of Ø%5 mm or more.</source>
        <translation>Bohrstange %1 (Ø%2 mm, Schneide %3 mm von ihrer Achse) passt nicht in die Bohrung Ø%4 mm, in die sie einfährt: Sie braucht eine Bohrung von Ø%5 mm oder mehr.</translation>
    </message>
    <message>
        <source>Boring bar %1 faces %2 only down to Ø%3 mm (further in, it would touch the opposite wall).</source>
        <translation>Bohrstange %1 plandreht %2 nur bis Ø%3 mm (weiter innen würde sie die gegenüberliegende Wand berühren).</translation>
    </message>
    <message>
        <source>The bottom of the bore inside the pilot hole, Ø%1 mm, is the drill&apos;s: it is not bored.</source>
        <translation>Der Bohrungsgrund innerhalb der Vorbohrung, Ø%1 mm, bleibt vom Bohrer: Er wird nicht ausgedreht.</translation>
    </message>
    <message>
        <source>The bar bores through to the held end: the chuck&apos;s or collet&apos;s bore must be free behind it.</source>
        <translation>Die Stange bohrt bis zum gespannten Ende durch: Die Bohrung des Futters oder der Spannzange muss dahinter frei sein.</translation>
    </message>
    <message>
        <source>The bore is bored from the free end with boring bar %1.</source>
        <translation>Die Bohrung wird vom freien Ende aus mit Bohrstange %1 ausgedreht.</translation>
    </message>
    <message>
        <source>The bottom of the bore, %1, is a cone or a radius down to the axis: the program finishes it to the axis, without the pilot hole&apos;s and the bar&apos;s limits of a flat bottom. Check that the bar clears the opposite wall there.</source>
        <translation>Der Bohrungsgrund %1 ist ein Kegel oder Radius bis zur Achse: Das Programm schlichtet ihn bis zur Achse, ohne die Grenzen von Vorbohrung und Stange wie bei einem ebenen Grund. Prüfen Sie, dass die Stange dort die gegenüberliegende Wand nicht berührt.</translation>
    </message>
    <message>
        <source>%1 is tighter than the nose radius %2 mm, and its neighbours give no corner to program instead: a control&apos;s compensation refuses it. Use an insert with a smaller nose, or --nose tip-path.</source>
        <translation>%1 ist enger als der Eckenradius %2 mm, und seine Nachbarn ergeben keine Ecke, die stattdessen programmiert werden kann: die Radiuskorrektur einer Steuerung lehnt es ab. Verwenden Sie eine Wendeschneidplatte mit kleinerem Eckenradius oder --nose tip-path.</translation>
    </message>
    <message>
        <source>The finishing pass cuts nothing: every outer feature of this set-up lies within the tool&apos;s stop of the %1. Grip the part shorter.</source>
        <translation>Der Schlichtschnitt schneidet nichts: jedes Außenformelement dieser Aufspannung liegt dort, wo das Werkzeug vor %1 anhält. Spannen Sie das Teil kürzer.</translation>
    </message>
    <message>
        <source>The pilot hole Ø%1 mm is as wide as the bore&apos;s narrowest Ø%2 mm or wider: nothing is left to bore there, and it stays the pilot hole&apos;s size, not the drawing&apos;s.</source>
        <translation>Die Vorbohrung Ø%1 mm ist so weit wie die engste Stelle der Bohrung, Ø%2 mm, oder weiter: dort bleibt nichts auszudrehen, und sie behält das Maß der Vorbohrung, nicht das der Zeichnung.</translation>
    </message>
    <message>
        <source>%1 falls at %2° in the feed direction, steeper than the insert&apos;s trailing edge (%3°) less the 2° of free cutting angle it needs: the finishing pass rides over it at %4° from z = %5 to %6 mm and leaves up to %7 mm of %8 uncut. Turn it from the other side or with a neutral tool.</source>
        <translation>%1 fällt in Vorschubrichtung unter %2° ab, steiler als die Nebenschneide der Wendeschneidplatte (%3°) abzüglich der 2° Freiwinkel, die sie braucht: Der Schlichtschnitt fährt unter %4° von z = %5 bis %6 mm darüber hinweg und lässt bis zu %7 mm von %8 stehen. Von der anderen Seite oder mit einem neutralen Werkzeug drehen.</translation>
    </message>
    <message>
        <source>%1 falls at %2° in the feed direction, steeper than the insert&apos;s trailing edge (%3°) less the 2° of free cutting angle it needs: the finishing pass stops at z = %4 mm and leaves up to %5 mm of %6 uncut. Turn it from the other side or with a neutral tool.</source>
        <translation>%1 fällt in Vorschubrichtung unter %2° ab, steiler als die Nebenschneide der Wendeschneidplatte (%3°) abzüglich der 2° Freiwinkel, die sie braucht: Der Schlichtschnitt endet bei z = %4 mm und lässt bis zu %5 mm von %6 stehen. Von der anderen Seite oder mit einem neutralen Werkzeug drehen.</translation>
    </message>
</context>
<context>
    <name>Undercuts</name>
    <message>
        <source>undercut %1 run-out</source>
        <translation>Auslauf von Freistich %1</translation>
    </message>
    <message>
        <source>undercut %1 bottom</source>
        <translation>Grund von Freistich %1</translation>
    </message>
    <message>
        <source>undercut %1 radius</source>
        <translation>Radius von Freistich %1</translation>
    </message>
    <message>
        <source>undercut %1 flank</source>
        <translation>Flanke von Freistich %1</translation>
    </message>
    <message>
        <source>an undercut is cut into a corner between two features; the %1 contour has no such corner %2</source>
        <translation>ein Freistich wird in eine Ecke zwischen zwei Formelementen eingestochen; die Kontur (%1) hat keine solche Ecke %2</translation>
    </message>
    <message>
        <source>a DIN 509 undercut sits where a cylinder meets a face, but corner %1 joins %2 and %3</source>
        <translation>ein Freistich nach DIN 509 liegt dort, wo ein Zylinder auf eine Planfläche trifft, aber Ecke %1 verbindet %2 und %3</translation>
    </message>
    <message>
        <source>corner %1 is an outside corner (face %2 falls away from cylinder %3): an undercut sits in the inside corner of a shoulder</source>
        <translation>Ecke %1 ist eine Außenecke (Planfläche %2 fällt vom Zylinder %3 ab): ein Freistich liegt in der Innenecke einer Schulter</translation>
    </message>
    <message>
        <source>cylinder %1 has no diameter (Ø%2 mm) to size an undercut for</source>
        <translation>Zylinder %1 hat keinen Durchmesser (Ø%2 mm), nach dem ein Freistich bemessen werden kann</translation>
    </message>
    <message>
        <source>cylinder %1 is %2 mm long, not longer than the width f = %3 mm of undercut %4</source>
        <translation>Zylinder %1 ist %2 mm lang, nicht länger als die Breite f = %3 mm von Freistich %4</translation>
    </message>
    <message>
        <source>face %1 rises %2 mm above cylinder %3, but undercut %4 meets it %5 mm above: the shoulder is too low for it</source>
        <translation>Planfläche %1 ragt %2 mm über Zylinder %3 hinaus, aber Freistich %4 trifft erst %5 mm darüber auf sie: die Schulter ist dafür zu niedrig</translation>
    </message>
    <message>
        <source>a groove is cut into a cylinder; %1 is not one</source>
        <translation>ein Einstich wird in einen Zylinder eingestochen; %1 ist keiner</translation>
    </message>
    <message>
        <source>the groove&apos;s width must be above zero, but is %1 mm</source>
        <translation>die Breite des Einstichs muss größer als null sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>the groove&apos;s depth must be above zero, but is %1 mm</source>
        <translation>die Tiefe des Einstichs muss größer als null sein, beträgt aber %1 mm</translation>
    </message>
    <message>
        <source>the groove from z = %1 mm to z = %2 mm must lie inside %3 (z %4 … %5 mm)</source>
        <translation>der Einstich von z = %1 mm bis z = %2 mm muss innerhalb von %3 liegen (z %4 … %5 mm)</translation>
    </message>
    <message>
        <source>a groove %1 mm deep would reach the axis from Ø%2 mm</source>
        <translation>ein Einstich von %1 mm Tiefe würde von Ø%2 mm aus die Achse erreichen</translation>
    </message>
    <message>
        <source>groove flank</source>
        <translation>Einstichflanke</translation>
    </message>
    <message>
        <source>groove bottom Ø%1</source>
        <translation>Einstichgrund Ø%1</translation>
    </message>
</context>
<context>
    <name>VerifyFeCommand</name>
    <message>
        <source>Solid check of %1 (%2): E = %3 MPa, nu = %4</source>
        <translation>Prüfung mit Volumenmodell von %1 (%2): E = %3 MPa, nu = %4</translation>
    </message>
    <message>
        <source>Force at each station: Fr = %1 N, Ft = %2 N, Fa = %3 N</source>
        <translation>Kraft an jeder Station: Fr = %1 N, Ft = %2 N, Fa = %3 N</translation>
    </message>
    <message>
        <source>Mesh: C3D10 of at most %1 mm, %2 nodes, %3 elements, %4 degrees of freedom; gmsh %5 s, CalculiX %6 s, beam %7 ms</source>
        <translation>Netz: C3D10 von höchstens %1 mm, %2 Knoten, %3 Elemente, %4 Freiheitsgrade; gmsh %5 s, CalculiX %6 s, Balken %7 ms</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>Check the beam against a solid model: the part meshed in quadratic tetrahedra with gmsh, held as its clamping holds it, loaded at N tool positions and solved with CalculiX; beam and solid deflection per station with the difference, the mesh size and degrees of freedom.</source>
        <translation>Den Balken mit einem Volumenmodell prüfen: das Teil mit gmsh in quadratische Tetraeder vernetzt, so gehalten, wie seine Einspannung es hält, an N Werkzeugpositionen belastet und mit CalculiX gelöst; Durchbiegung von Balken und Volumenmodell je Station mit der Differenz, die Netzgröße und die Freiheitsgrade.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Das Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <source>Tool positions along the part, 1 to %1 (default 5).</source>
        <translation>Werkzeugpositionen entlang des Teils, 1 bis %1 (Standard 5).</translation>
    </message>
    <message>
        <source>Largest element edge in mm (default: a fifth of the smallest turned diameter, at least 1 mm).</source>
        <translation>Größte Elementkante in mm (Standard: ein Fünftel des kleinsten gedrehten Durchmessers, mindestens 1 mm).</translation>
    </message>
    <message>
        <source>Forces radial, tangential, axial in N instead of the pass&apos;s.</source>
        <translation>Kräfte radial, tangential, axial in N statt der Kräfte des Schnitts.</translation>
    </message>
    <message>
        <source>Report the progress on standard error, as lines &quot;progress F&quot; with F from 0 to 1.</source>
        <translation>Den Fortschritt auf der Standardfehlerausgabe melden, als Zeilen „progress F“ mit F von 0 bis 1.</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>Die Projektdatei.</translation>
    </message>
    <message>
        <source>--stations: &quot;%1&quot; is not a whole number from 1 to %2</source>
        <translation>--stations: „%1“ ist keine ganze Zahl von 1 bis %2</translation>
    </message>
    <message>
        <source>--mesh-size: &quot;%1&quot; is not a length from 0.2 to 100 mm</source>
        <translation>--mesh-size: „%1“ ist keine Länge von 0,2 bis 100 mm</translation>
    </message>
    <message>
        <source>--load: &quot;%1&quot; is not three forces Fr,Ft,Fa in N</source>
        <translation>--load: „%1“ sind keine drei Kräfte Fr,Ft,Fa in N</translation>
    </message>
    <message>
        <source>Largest radial difference: %1 % of the largest deflection</source>
        <translation>Größte radiale Abweichung: %1 % der größten Durchbiegung</translation>
    </message>
    <message>
        <source>Beam: corrected for the root in the jaws and the shoulders (docs/solid-fe.md); Timoshenko: without the corrections</source>
        <translation>Balken: korrigiert für die Einspannung in den Backen und die Absätze (docs/solid-fe.md); Timoshenko: ohne die Korrekturen</translation>
    </message>
    <message>
        <source>Beam: Timoshenko, without the corrections (--uncorrected-beam)</source>
        <translation>Balken: Timoshenko, ohne die Korrekturen (--uncorrected-beam)</translation>
    </message>
    <message>
        <source>  z [mm]   D [mm]   radial deflection [um]: beam    solid   beam-solid [%]   tangential [um]: beam    solid   Timoshenko radial [um]</source>
        <translation>  z [mm]   D [mm]  Durchbiegung rad. [um]: Balken  Volumen  Balken-Vol. [%]  tangential [um]: Balken  Volumen   Timoshenko radial [um]</translation>
    </message>
    <message>
        <source>Compare the beam without its corrections for the root in the jaws and the shoulders.</source>
        <translation>Den Balken ohne seine Korrekturen für die Einspannung in den Backen und die Absätze vergleichen.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tolerance-aware planning of CNC turning.</source>
        <translation>Toleranzgerechte Planung der CNC-Drehbearbeitung.</translation>
    </message>
    <message>
        <source>Project file to open (.tolturn).</source>
        <translation>Zu öffnende Projektdatei (.tolturn).</translation>
    </message>
</context>
<context>
    <name>tolturn::AboutDialog</name>
    <message>
        <source>&lt;p&gt;Tolerance-aware planning of CNC turning: deflection of machine, workpiece and tool, ISO 286 and ISO 1101 verdicts, and cutting conditions that hold them.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later). There is no warranty.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Toleranzgerechte Planung der CNC-Drehbearbeitung: Verformung von Maschine, Werkstück und Werkzeug, Bewertungen nach ISO 286 und ISO 1101 sowie Schnittbedingungen, die diese einhalten.&lt;/p&gt;&lt;p&gt;Lizenziert unter der GNU General Public License, Version 3 oder neuer (GPL-3.0-or-later). Es besteht keinerlei Gewährleistung.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Built with</source>
        <translation>Erstellt mit</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>Version</translation>
    </message>
    <message>
        <source>Licence</source>
        <translation>Lizenz</translation>
    </message>
    <message>
        <source>About TolTurn</source>
        <translation>Über TolTurn</translation>
    </message>
</context>
<context>
    <name>tolturn::AdaptiveTab</name>
    <message>
        <source>The pass of the plan simulated under constant-force control</source>
        <translation>Der unter Konstantkraftregelung simulierte Schnitt des Plans</translation>
    </message>
    <message>
        <source>Force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <source>Feed [mm/rev]</source>
        <translation>Vorschub [mm/U]</translation>
    </message>
    <message>
        <source>Deviation [µm]</source>
        <translation>Abweichung [µm]</translation>
    </message>
    <message>
        <source>Roughness Ra [µm]</source>
        <translation>Rauheit Ra [µm]</translation>
    </message>
    <message>
        <source>Depth of cut [mm]</source>
        <translation>Schnitttiefe [mm]</translation>
    </message>
    <message>
        <source>Machine noise (Čuš &amp; Župerl §2.4): the standard deviation of the measured force. The paper states no level; none unless given.</source>
        <translation>Maschinenrauschen (Čuš &amp; Župerl §2.4): die Standardabweichung der gemessenen Kraft. Der Aufsatz nennt keine Höhe; keines, wenn nicht angegeben.</translation>
    </message>
    <message>
        <source>Machine noise:</source>
        <translation>Maschinenrauschen:</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Scheduled f [mm/rev]</source>
        <translation>f nach Plan [mm/U]</translation>
    </message>
    <message>
        <source>Programmed f [mm/rev]</source>
        <translation>f programmiert [mm/U]</translation>
    </message>
    <message>
        <source>Limited by</source>
        <translation>Begrenzt durch</translation>
    </message>
    <message>
        <source>The finishing pass feature by feature: the largest feed of the plan&apos;s feed range that holds the feature&apos;s tolerances and the pass&apos;s roughness, power and force limits</source>
        <translation>Der Schlichtschnitt Formelement für Formelement: der größte Vorschub des Vorschubbereichs der Planung, der die Toleranzen des Formelements und die Rauheits-, Leistungs- und Kraftgrenzen des Schnitts hält</translation>
    </message>
    <message>
        <source>&lt;b&gt;Feed schedule of the finishing pass&lt;/b&gt;</source>
        <translation>&lt;b&gt;Vorschubplan des Schlichtschnitts&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Pass %1 (roughing)</source>
        <translation>Schnitt %1 (Schruppen)</translation>
    </message>
    <message>
        <source>Pass %1 (finishing)</source>
        <translation>Schnitt %1 (Schlichten)</translation>
    </message>
    <message>
        <source>No pass to simulate.</source>
        <translation>Kein Schnitt zu simulieren.</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation>Schnitttiefe</translation>
    </message>
    <message>
        <source>programmed feed</source>
        <translation>programmierter Vorschub</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptiv</translation>
    </message>
    <message>
        <source>Set force %1 N (the programmed feed&apos;s at a_p %2 mm). In the cut %3 s at the programmed feed, %4 s adaptive (%5 % saved); peak force %6 N and %7 N; deviation %8–%9 µm and %10–%11 µm.</source>
        <translation>Sollkraft %1 N (die des programmierten Vorschubs bei a_p %2 mm). Im Schnitt %3 s beim programmierten Vorschub, %4 s adaptiv (%5 % gespart); Spitzenkraft %6 N und %7 N; Abweichung %8–%9 µm und %10–%11 µm.</translation>
    </message>
    <message>
        <source>No feed schedule: %1</source>
        <translation>Kein Vorschubplan: %1</translation>
    </message>
    <message>
        <source>kept: %1 is not held at any feed of the range</source>
        <translation>beibehalten: %1 wird bei keinem Vorschub des Bereichs gehalten</translation>
    </message>
    <message>
        <source>Finishing pass: %1 s at the programmed feed, %2 s scheduled (%3 %). Tick Feed schedule on the G-code tab to program it.</source>
        <translation>Schlichtschnitt: %1 s beim programmierten Vorschub, %2 s nach Plan (%3 %). Vorschubplan im Reiter G-Code ankreuzen, um ihn zu programmieren.</translation>
    </message>
</context>
<context>
    <name>tolturn::CadFileController</name>
    <message>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <source>Import of %1 cancelled; the project is unchanged.</source>
        <translation>Import von %1 abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>Import of %1 cancelled.</source>
        <translation>Import von %1 abgebrochen.</translation>
    </message>
    <message>
        <source>Cannot import %1</source>
        <translation>%1 kann nicht importiert werden</translation>
    </message>
    <message>
        <source>The part was not imported; the current project is unchanged.

%1</source>
        <translation>Das Teil wurde nicht importiert; das aktuelle Projekt ist unverändert.

%1</translation>
    </message>
    <message>
        <source>%1 could not be imported:</source>
        <translation>%1 konnte nicht importiert werden:</translation>
    </message>
    <message>
        <source>Imported %1: %2 outer and %3 inner features, %4 warning(s); set material, machine, tool and clamping, then save.</source>
        <translation>%1 importiert: %2 äußere und %3 innere Formelemente, %4 Warnung(en); legen Sie Werkstoff, Maschine, Werkzeug und Aufspannung fest und speichern Sie dann.</translation>
    </message>
    <message>
        <source>Imported from %1; left out or noted:</source>
        <translation>Aus %1 importiert; weggelassen oder vermerkt:</translation>
    </message>
    <message>
        <source>Cannot export %1</source>
        <translation>%1 kann nicht exportiert werden</translation>
    </message>
    <message>
        <source>Exported the part as a revolved solid to %1</source>
        <translation>Das Teil wurde als Rotationskörper nach %1 exportiert</translation>
    </message>
    <message>
        <source>Extracting the part from %1…</source>
        <translation>Teil wird aus %1 extrahiert …</translation>
    </message>
</context>
<context>
    <name>tolturn::CadReaderProcess</name>
    <message>
        <source>The CAD reader &apos;%1&apos; is missing: TolTurn reads STEP and IGES files with tolturn-cli, which is installed beside it. Install TolTurn again.</source>
        <translation>Das CAD-Leseprogramm „%1“ fehlt: TolTurn liest STEP- und IGES-Dateien mit tolturn-cli, das neben ihm installiert ist. Installieren Sie TolTurn erneut.</translation>
    </message>
    <message>
        <source>No temporary folder for the import: %1</source>
        <translation>Kein temporärer Ordner für den Import: %1</translation>
    </message>
    <message>
        <source>The CAD reader &apos;%1&apos; could not be started: %2</source>
        <translation>Das CAD-Leseprogramm „%1“ konnte nicht gestartet werden: %2</translation>
    </message>
    <message>
        <source>Reading %1 ended the CAD reader (OpenCascade) abnormally; the program and the project are not affected. The file is probably damaged: check it in the CAD system that wrote it.%2</source>
        <translation>Das Lesen von %1 hat das CAD-Leseprogramm (OpenCascade) abnormal beendet; Programm und Projekt sind nicht betroffen. Die Datei ist wahrscheinlich beschädigt: prüfen Sie sie im CAD-System, das sie geschrieben hat.%2</translation>
    </message>
    <message>
        <source>The CAD reader gave no result for %1 (exit code %2): %3 %4</source>
        <translation>Das CAD-Leseprogramm lieferte kein Ergebnis für %1 (Exit-Code %2): %3 %4</translation>
    </message>
</context>
<context>
    <name>tolturn::DeflectionPanel</name>
    <message>
        <source>Outer contour</source>
        <translation>Außenkontur</translation>
    </message>
    <message>
        <source>Inner contour (bores)</source>
        <translation>Innenkontur (Bohrungen)</translation>
    </message>
    <message>
        <source>Radial deviation by contribution</source>
        <translation>Radialabweichung nach Anteil</translation>
    </message>
    <message>
        <source>Tangential deviation by contribution</source>
        <translation>Tangentialabweichung nach Anteil</translation>
    </message>
    <message>
        <source>Diameter error</source>
        <translation>Durchmesserfehler</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>spindle–chuck / supports</source>
        <translation>Spindel–Futter / Abstützungen</translation>
    </message>
    <message>
        <source>workpiece</source>
        <translation>Werkstück</translation>
    </message>
    <message>
        <source>toolpost</source>
        <translation>Werkzeugträger</translation>
    </message>
    <message>
        <source>thermal</source>
        <translation>thermisch</translation>
    </message>
    <message>
        <source>Radial deviation (material left on the surface)</source>
        <translation>Radialabweichung (auf der Oberfläche stehen gebliebenes Material)</translation>
    </message>
    <message>
        <source>Tangential deviation</source>
        <translation>Tangentialabweichung</translation>
    </message>
    <message>
        <source>diameter error</source>
        <translation>Durchmesserfehler</translation>
    </message>
    <message>
        <source>Diameter error: machined minus nominal</source>
        <translation>Durchmesserfehler: gefertigt minus nominal</translation>
    </message>
    <message>
        <source>Forces (%1): Fc %2 N, Ff %3 N, Fp %4 N · pass %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm</source>
        <translation>Kräfte (%1): Fc %2 N, Ff %3 N, Fp %4 N · Schnitt %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm</translation>
    </message>
    <message>
        <source>Error: </source>
        <translation>Fehler: </translation>
    </message>
    <message>
        <source>Warning: </source>
        <translation>Warnung: </translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [%1]</source>
        <translation>z ab dem linken Ende des Werkstücks [%1]</translation>
    </message>
    <message>
        <source>deviation [%1]</source>
        <translation>Abweichung [%1]</translation>
    </message>
    <message>
        <source>diameter error [%1]</source>
        <translation>Durchmesserfehler [%1]</translation>
    </message>
    <message>
        <source>Face conicity</source>
        <translation>Konizität der Planflächen</translation>
    </message>
    <message>
        <source>Radial deviation: material left on the surface, δ_T = δ_sc + δ_tp + δ_p + δ_th (Valiño et al. 2008, eq. 2). Diameter error: 2 (r - r_nominal) with the radial and tangential deviation combined exactly. Face conicity: the axial run-out e = h · tan θ of each faced surface, tan θ = dδ/dz at the face (eq. 12).</source>
        <translation>Radialabweichung: auf der Oberfläche stehen gebliebenes Material, δ_T = δ_sc + δ_tp + δ_p + δ_th (Valiño et al. 2008, Gl. 2). Durchmesserfehler: 2 (r - r_nominal), mit exakt kombinierter Radial- und Tangentialabweichung. Konizität der Planflächen: der Planlauf e = h · tan θ jeder plangedrehten Fläche, tan θ = dδ/dz an der Planfläche (Gl. 12).</translation>
    </message>
    <message>
        <source>axial run-out e of each face</source>
        <translation>Planlauf e jeder Planfläche</translation>
    </message>
    <message>
        <source>Face conicity: axial run-out of each face</source>
        <translation>Konizität der Planflächen: Planlauf jeder Planfläche</translation>
    </message>
    <message>
        <source>axial run-out e [%1]</source>
        <translation>Planlauf e [%1]</translation>
    </message>
    <message>
        <source>%1, compliant end of the machine range</source>
        <translation>%1, nachgiebiges Ende des Maschinenbereichs</translation>
    </message>
    <message>
        <source>%1 over the machine&apos;s stiffness range</source>
        <translation>%1 über den Steifigkeitsbereich der Maschine</translation>
    </message>
    <message>
        <source>The predicted deviation of every feature appears here once a part is open.</source>
        <translation>Die vorhergesagte Abweichung jedes Formelements erscheint hier, sobald ein Teil geöffnet ist.</translation>
    </message>
    <message>
        <source>total, physics + learned</source>
        <translation>gesamt, Physik + Gelerntes</translation>
    </message>
    <message>
        <source>diameter error, physics + learned</source>
        <translation>Durchmesserfehler, Physik + Gelerntes</translation>
    </message>
    <message>
        <source>Physics + learned (%1): what was learned of the machine from its measured parts is added to the physics; the band is ± the RMS error on parts not learned from (%2 µm).</source>
        <translation>Physik + Gelerntes (%1): Was von der Maschine aus ihren gemessenen Teilen gelernt wurde, wird zur Physik addiert; das Band ist ± der RMS-Fehler bei nicht gelernten Teilen (%2 µm).</translation>
    </message>
    <message>
        <source>%1 − %2 µm</source>
        <translation>%1 − %2 µm</translation>
    </message>
    <message>
        <source>%1 + %2 µm</source>
        <translation>%1 + %2 µm</translation>
    </message>
    <message>
        <source>boring bar</source>
        <translation>Bohrstange</translation>
    </message>
    <message>
        <source> · bores: bar %1, L/D %2, Fc %3 N, Ff %4 N, Fp %5 N, %6 µm/N at its tip</source>
        <translation> · Bohrungen: Stange %1, L/D %2, Fc %3 N, Ff %4 N, Fp %5 N, %6 µm/N an der Spitze</translation>
    </message>
    <message>
        <source>z from the held (right) end [%1]</source>
        <translation>z vom gespannten (rechten) Ende [%1]</translation>
    </message>
</context>
<context>
    <name>tolturn::DiagnosticsPanel</name>
    <message>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
</context>
<context>
    <name>tolturn::EndMillingExampleDialog</name>
    <message>
        <source>Čuš &amp; Župerl end-milling example</source>
        <translation>Stirnfräsbeispiel von Čuš &amp; Župerl</translation>
    </message>
    <message>
        <source>Force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <source>Feed rate [mm/min]</source>
        <translation>Vorschubgeschwindigkeit [mm/min]</translation>
    </message>
    <message>
        <source>Spindle speed [1/min]</source>
        <translation>Drehzahl [1/min]</translation>
    </message>
    <message>
        <source>Roughness Ra, M5 [µm]</source>
        <translation>Rauheit Ra, M5 [µm]</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force (004 gives no level)</source>
        <translation>Maschinenrauschen: Standardabweichung der gemessenen Kraft (004 nennt keinen Wert)</translation>
    </message>
    <message>
        <source>Share of a change of chip load the spindle speed takes (0: the feed alone)</source>
        <translation>Anteil einer Änderung der Spandicke, den die Drehzahl übernimmt (0: nur der Vorschub)</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>Rauschen</translation>
    </message>
    <message>
        <source>Speed share</source>
        <translation>Anteil Drehzahl</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Artikel</translation>
    </message>
    <message>
        <source>Speed [1/min]</source>
        <translation>Drehzahl [1/min]</translation>
    </message>
    <message>
        <source>Ra, M5 [µm]</source>
        <translation>Ra, M5 [µm]</translation>
    </message>
    <message>
        <source>paper: 181.1 N held</source>
        <translation>Artikel: 181,1 N gehalten</translation>
    </message>
    <message>
        <source>paper: 324.61 mm/min after control</source>
        <translation>Artikel: 324,61 mm/min nach Regelung</translation>
    </message>
    <message>
        <source>paper: 2201 1/min after control</source>
        <translation>Artikel: 2201 1/min nach Regelung</translation>
    </message>
    <message>
        <source>paper: Ra 0.79 µm produced</source>
        <translation>Artikel: Ra 0,79 µm erzeugt</translation>
    </message>
    <message>
        <source>Table 1, simulation 5: from 430.41 mm/min and 1610 1/min to 181.1 N</source>
        <translation>Tabelle 1, Simulation 5: von 430,41 mm/min und 1610 1/min auf 181,1 N</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>without control</source>
        <translation>ohne Regelung</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptiv</translation>
    </message>
    <message>
        <source>Force network 8–15–3 (ArcTangent, back-propagation) trained on the mean forces of the linear edge-force model for Al7075-T6 (004&apos;s cut data are not published): %1 % RMS error on cut data it has not seen. Tool Ø%2 mm, %3 flutes, down milling %4 mm wide, %5 mm deep (the depth at which the model gives the paper&apos;s 181.1 N at its controlled conditions). PSO-NN off line: %6 mm/min at %7 1/min within %8 N. Ra from the printed M5 (eq. 6), which does not reproduce the paper&apos;s table; the spindle follows the feed drive&apos;s eq. 1 (004 gives no spindle model). * outside the network&apos;s training range.</source>
        <translation>Kraftnetz 8–15–3 (ArcTangens, Backpropagation), trainiert an den mittleren Kräften des linearen Schneidkantenkraftmodells für Al7075-T6 (die Schnittdaten von 004 sind nicht veröffentlicht): %1 % Effektivfehler an Schnittdaten, die es nicht gesehen hat. Werkzeug Ø%2 mm, %3 Schneiden, Gleichlauffräsen %4 mm breit, %5 mm tief (die Tiefe, bei der das Modell die 181,1 N des Artikels bei seinen geregelten Bedingungen ergibt). PSO-NN offline: %6 mm/min bei %7 1/min innerhalb %8 N. Ra aus dem gedruckten M5 (Gl. 6), das die Tabelle des Artikels nicht wiedergibt; die Spindel folgt Gl. 1 des Vorschubantriebs (004 gibt kein Spindelmodell an). * außerhalb des Trainingsbereichs des Netzes.</translation>
    </message>
</context>
<context>
    <name>tolturn::FeaturePanel</name>
    <message>
        <source>z of the start, from the part&apos;s left end</source>
        <translation>z des Anfangs, ab linkem Teilende</translation>
    </message>
    <message>
        <source>Diameter at the start</source>
        <translation>Durchmesser am Anfang</translation>
    </message>
    <message>
        <source>z of the end</source>
        <translation>z des Endes</translation>
    </message>
    <message>
        <source>Diameter at the end</source>
        <translation>Durchmesser am Ende</translation>
    </message>
    <message>
        <source>Where the step is, inside the cylinder</source>
        <translation>Lage des Absatzes innerhalb des Zylinders</translation>
    </message>
    <message>
        <source>Diameter after the step</source>
        <translation>Durchmesser nach dem Absatz</translation>
    </message>
    <message>
        <source>Insert &amp;Step</source>
        <translation>&amp;Absatz einfügen</translation>
    </message>
    <message>
        <source>Chamfer leg (45°) or radius</source>
        <translation>Fasenlänge (45°) oder Radius</translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation>Formelement &amp;löschen</translation>
    </message>
    <message>
        <source>Make C&amp;one</source>
        <translation>In &amp;Kegel umwandeln</translation>
    </message>
    <message>
        <source>Depth of the bore from this end face; the part&apos;s length bores through</source>
        <translation>Tiefe der Bohrung ab dieser Stirnfläche; die Teillänge ergibt eine Durchgangsbohrung</translation>
    </message>
    <message>
        <source>Diameter of the bore</source>
        <translation>Durchmesser der Bohrung</translation>
    </message>
    <message>
        <source>&amp;Bore from This Face</source>
        <translation>&amp;Bohrung von dieser Stirnfläche</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Ecken</translation>
    </message>
    <message>
        <source>Start z:</source>
        <translation>Anfang z:</translation>
    </message>
    <message>
        <source>Start Ø:</source>
        <translation>Anfang Ø:</translation>
    </message>
    <message>
        <source>End z:</source>
        <translation>Ende z:</translation>
    </message>
    <message>
        <source>End Ø:</source>
        <translation>Ende Ø:</translation>
    </message>
    <message>
        <source>Step (cylinders)</source>
        <translation>Absatz (Zylinder)</translation>
    </message>
    <message>
        <source>At z:</source>
        <translation>Bei z:</translation>
    </message>
    <message>
        <source>To Ø:</source>
        <translation>Auf Ø:</translation>
    </message>
    <message>
        <source>Break a corner</source>
        <translation>Ecke brechen</translation>
    </message>
    <message>
        <source>Size:</source>
        <translation>Größe:</translation>
    </message>
    <message>
        <source>Chamfer start</source>
        <translation>Fase am Anfang</translation>
    </message>
    <message>
        <source>Chamfer end</source>
        <translation>Fase am Ende</translation>
    </message>
    <message>
        <source>Round start</source>
        <translation>Radius am Anfang</translation>
    </message>
    <message>
        <source>Round end</source>
        <translation>Radius am Ende</translation>
    </message>
    <message>
        <source>Bore (solid part, end face)</source>
        <translation>Bohrung (Vollteil, Stirnfläche)</translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation>Tiefe:</translation>
    </message>
    <message>
        <source>Ø:</source>
        <translation>Ø:</translation>
    </message>
    <message>
        <source>Click a feature of the drawing to edit it.</source>
        <translation>Klicken Sie auf ein Formelement der Zeichnung, um es zu bearbeiten.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; %2 — %3, %4 contour</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; %2 — %3, Kontur %4</translation>
    </message>
    <message>
        <source>Make C&amp;ylinder</source>
        <translation>In &amp;Zylinder umwandeln</translation>
    </message>
    <message>
        <source>Move corner of %1</source>
        <translation>Ecke von %1 verschieben</translation>
    </message>
    <message>
        <source>Move corner to z %1, Ø %2</source>
        <translation>Ecke nach z %1, Ø %2 verschieben</translation>
    </message>
    <message>
        <source>Insert step into %1</source>
        <translation>Absatz in %1 einfügen</translation>
    </message>
    <message>
        <source>Round corner of %1</source>
        <translation>Ecke von %1 verrunden</translation>
    </message>
    <message>
        <source>Chamfer corner of %1</source>
        <translation>Ecke von %1 anfasen</translation>
    </message>
    <message>
        <source>Make %1 a cylinder</source>
        <translation>%1 in Zylinder umwandeln</translation>
    </message>
    <message>
        <source>Make %1 a cone</source>
        <translation>%1 in Kegel umwandeln</translation>
    </message>
    <message>
        <source>Bore from %1</source>
        <translation>Bohrung von %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <source>Make R&amp;ound</source>
        <translation>In &amp;Rundung umwandeln</translation>
    </message>
    <message>
        <source>Make C&amp;hamfer</source>
        <translation>In F&amp;ase umwandeln</translation>
    </message>
    <message>
        <source>Make %1 an edge round</source>
        <translation>%1 in Kantenrundung umwandeln</translation>
    </message>
    <message>
        <source>Make %1 a chamfer</source>
        <translation>%1 in Fase umwandeln</translation>
    </message>
    <message>
        <source>Where the groove starts, inside the cylinder (its left flank)</source>
        <translation>Beginn des Einstichs innerhalb des Zylinders (seine linke Flanke)</translation>
    </message>
    <message>
        <source>Width of the groove along z</source>
        <translation>Breite des Einstichs entlang z</translation>
    </message>
    <message>
        <source>Depth of the groove, radially</source>
        <translation>Tiefe des Einstichs, radial</translation>
    </message>
    <message>
        <source>Insert &amp;Groove</source>
        <translation>&amp;Einstich einfügen</translation>
    </message>
    <message>
        <source>Undercut start</source>
        <translation>Freistichbeginn</translation>
    </message>
    <message>
        <source>Undercut end</source>
        <translation>Freistichende</translation>
    </message>
    <message>
        <source>Groove and undercut (cylinders)</source>
        <translation>Einstich und Freistich (Zylinder)</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>Breite:</translation>
    </message>
    <message>
        <source>DIN 509 form E (cylinder)</source>
        <translation>DIN 509 Form E (Zylinder)</translation>
    </message>
    <message>
        <source>DIN 509 form F (cylinder and face)</source>
        <translation>DIN 509 Form F (Zylinder und Planfläche)</translation>
    </message>
    <message>
        <source>The undercut is sized for the cylinder&apos;s diameter by DIN 509 Table 1 and cut into the corner where the cylinder meets a shoulder</source>
        <translation>Der Freistich wird nach DIN 509 Tabelle 1 für den Durchmesser des Zylinders bemessen und in die Ecke eingestochen, in der der Zylinder auf eine Schulter trifft</translation>
    </message>
    <message>
        <source>DIN 509 Table 1 for Ø%1 mm: E or F %2 × %3 (r × t1), width f %4 mm, recess into the face t2 %5 mm (form F)</source>
        <translation>DIN 509 Tabelle 1 für Ø%1 mm: E oder F %2 × %3 (r × t1), Breite f %4 mm, Einstich in die Planfläche t2 %5 mm (Form F)</translation>
    </message>
    <message>
        <source>Insert groove into %1</source>
        <translation>Einstich in %1 einfügen</translation>
    </message>
    <message>
        <source>Insert DIN 509 undercut at %1</source>
        <translation>Freistich nach DIN 509 an %1 einfügen</translation>
    </message>
</context>
<context>
    <name>tolturn::FileController</name>
    <message>
        <source>TolTurn projects (*.tolturn *.json);;All files (*)</source>
        <translation>TolTurn-Projekte (*.tolturn *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>New part</source>
        <translation>Neues Teil</translation>
    </message>
    <message>
        <source>New project: a plain bar to shape</source>
        <translation>Neues Projekt: ein glatter Stab als Ausgangsform</translation>
    </message>
    <message>
        <source>Cannot open %1</source>
        <translation>%1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>The file was not opened; the current project is unchanged.

%1</source>
        <translation>Die Datei wurde nicht geöffnet; das aktuelle Projekt ist unverändert.

%1</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>the unsaved project &quot;%1&quot;</source>
        <translation>das nicht gespeicherte Projekt „%1“</translation>
    </message>
    <message>
        <source>Cannot recover %1</source>
        <translation>%1 kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <source>The copy %1 cannot be read; it is kept.

%2</source>
        <translation>Die Kopie %1 kann nicht gelesen werden; sie wird aufbewahrt.

%2</translation>
    </message>
    <message>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation>%1 im Stand von %2 wiederhergestellt; speichern Sie es, um es zu behalten.</translation>
    </message>
    <message>
        <source>Cannot export the report</source>
        <translation>Der Bericht kann nicht exportiert werden</translation>
    </message>
    <message numerus="yes">
        <source>Report written to %1 (%n page(s))</source>
        <translation>
            <numerusform>Bericht nach %1 geschrieben (%n Seite)</numerusform>
            <numerusform>Bericht nach %1 geschrieben (%n Seiten)</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot save %1</source>
        <translation>%1 kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>The project was not saved; the file on disk is unchanged.

%1</source>
        <translation>Das Projekt wurde nicht gespeichert; die Datei auf dem Datenträger ist unverändert.

%1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Writing the report…</source>
        <translation>Bericht wird geschrieben…</translation>
    </message>
    <message>
        <source>Report cancelled; nothing was written.</source>
        <translation>Bericht abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1 with %n problem(s) to repair before it can be computed</source>
        <translation>
            <numerusform>%1 mit %n Problem geöffnet, das vor der Berechnung zu beheben ist</numerusform>
            <numerusform>%1 mit %n Problemen geöffnet, die vor der Berechnung zu beheben sind</numerusform>
        </translation>
    </message>
    <message>
        <source>Computing the report failed: %1</source>
        <translation>Die Berechnung des Berichts ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>tolturn::ForceModelEditor</name>
    <message>
        <source>Force model and shop conditions</source>
        <translation>Kraftmodell und Werkstattbedingungen</translation>
    </message>
    <message>
        <source>Kienzle</source>
        <translation>Kienzle</translation>
    </message>
    <message>
        <source>Li &amp; Du</source>
        <translation>Li &amp; Du</translation>
    </message>
    <message>
        <source>material&apos;s</source>
        <translation>des Werkstoffs</translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation>nicht angepasst</translation>
    </message>
    <message>
        <source>not given: 20 °C</source>
        <translation>nicht angegeben: 20 °C</translation>
    </message>
    <message>
        <source>not given: 0 (cold start)</source>
        <translation>nicht angegeben: 0 (Kaltstart)</translation>
    </message>
    <message>
        <source> MPa</source>
        <translation> MPa</translation>
    </message>
    <message>
        <source> °C</source>
        <translation> °C</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>F_f/F_c for the Kienzle model, replacing the material data&apos;s ratio</source>
        <translation>F_f/F_c für das Kienzle-Modell, ersetzt das Verhältnis der Werkstoffdaten</translation>
    </message>
    <message>
        <source>F_p/F_c for the Kienzle model, replacing the material data&apos;s ratio</source>
        <translation>F_p/F_c für das Kienzle-Modell, ersetzt das Verhältnis der Werkstoffdaten</translation>
    </message>
    <message>
        <source>Ambient temperature of the shop, for the thermal drift (not given: the ISO 1 reference temperature, 20 °C)</source>
        <translation>Umgebungstemperatur der Werkstatt, für die thermische Drift (nicht angegeben: die Bezugstemperatur nach ISO 1, 20 °C)</translation>
    </message>
    <message>
        <source>Time since the machine was started, for the thermal warm-up (not given: a cold machine, 0 min)</source>
        <translation>Zeit seit dem Einschalten der Maschine, für die Erwärmung (nicht angegeben: kalte Maschine, 0 min)</translation>
    </message>
    <message>
        <source>&amp;Model:</source>
        <translation>&amp;Modell:</translation>
    </message>
    <message>
        <source>F_f/F_c:</source>
        <translation>F_f/F_c:</translation>
    </message>
    <message>
        <source>F_p/F_c:</source>
        <translation>F_p/F_c:</translation>
    </message>
    <message>
        <source>K_n:</source>
        <translation>K_n:</translation>
    </message>
    <message>
        <source>K_f:</source>
        <translation>K_f:</translation>
    </message>
    <message>
        <source>Ambient:</source>
        <translation>Umgebung:</translation>
    </message>
    <message>
        <source>Since start:</source>
        <translation>Seit Start:</translation>
    </message>
    <message>
        <source>Kienzle: F_c from kc1.1 and mc of the material, F_f and F_p as ratios of it. Li &amp; Du (2002, eq. 15–20): normal pressure K_n and friction ratio K_f fitted to measured forces (tolturn-cli calibrate-forces).</source>
        <translation>Kienzle: F_c aus kc1.1 und mc des Werkstoffs, F_f und F_p als Verhältnisse dazu. Li &amp; Du (2002, Gl. 15–20): Normaldruck K_n und Reibungsverhältnis K_f, an gemessene Kräfte angepasst (tolturn-cli calibrate-forces).</translation>
    </message>
    <message>
        <source>K_n of Li &amp; Du (2002): normal pressure on the rake face</source>
        <translation>K_n nach Li &amp; Du (2002): Normaldruck auf der Spanfläche</translation>
    </message>
    <message>
        <source>K_f of Li &amp; Du (2002): friction force over normal force</source>
        <translation>K_f nach Li &amp; Du (2002): Reibkraft durch Normalkraft</translation>
    </message>
</context>
<context>
    <name>tolturn::HelpBrowser</name>
    <message>
        <source>TolTurn User Guide</source>
        <translation>TolTurn-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Contents</source>
        <translation>&amp;Inhalt</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
</context>
<context>
    <name>tolturn::ImportDialog</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: a turned part %2 mm long, Ø max %3 mm, with %4 outer and %5 inner features; %6 warning(s), listed after the import.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: ein Drehteil, %2 mm lang, Ø max. %3 mm, mit %4 äußeren und %5 inneren Formelementen; %6 Warnung(en), die nach dem Import aufgeführt werden.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Body %1: %2 mm³, %3 faces</source>
        <translation>Körper %1: %2 mm³, %3 Flächen</translation>
    </message>
    <message>
        <source>Axis %1: through %2 along %3, %4 revolved faces</source>
        <translation>Achse %1: durch %2 in Richtung %3, %4 Rotationsflächen</translation>
    </message>
    <message>
        <source>The common axis of the body&apos;s cylindrical, conical, toroidal and spherical faces; the one with the most revolved area is proposed.</source>
        <translation>Die gemeinsame Achse der zylindrischen, kegeligen, torusförmigen und kugelförmigen Flächen des Körpers; vorgeschlagen wird die Achse mit der größten Rotationsfläche.</translation>
    </message>
    <message>
        <source>Chuck at the model&apos;s other end (turn the part end for end)</source>
        <translation>Spannfutter am anderen Ende des Modells (Teil wenden)</translation>
    </message>
    <message>
        <source>z = 0 is the part&apos;s left end, the end held in the chuck. Tick to put the model&apos;s right end there instead.</source>
        <translation>z = 0 ist das linke Ende des Teils, das im Spannfutter gehaltene Ende. Aktivieren Sie diese Option, um stattdessen das rechte Ende des Modells dorthin zu legen.</translation>
    </message>
    <message>
        <source>&amp;Body:</source>
        <translation>&amp;Körper:</translation>
    </message>
    <message>
        <source>&amp;Axis:</source>
        <translation>&amp;Achse:</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>&amp;Importieren</translation>
    </message>
</context>
<context>
    <name>tolturn::MainWindow</name>
    <message>
        <source>Open a project (File &gt; Open) or an example part (File &gt; Open Example).</source>
        <translation>Öffnen Sie ein Projekt (Datei &gt; Öffnen) oder ein Beispielteil (Datei &gt; Beispiel öffnen).</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation>Formelement &amp;löschen</translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation>Einrichtung</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Toleranzen</translation>
    </message>
    <message>
        <source>Deflection</source>
        <translation>Verformung</translation>
    </message>
    <message>
        <source>Planning</source>
        <translation>Planung</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>Open &amp;Example</source>
        <translation>&amp;Beispiel öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Export &amp;Report…</source>
        <translation>Bericht e&amp;xportieren…</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>B&amp;eenden</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About TolTurn</source>
        <translation>Ü&amp;ber TolTurn</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <source>%1[*] — TolTurn</source>
        <translation>%1[*] — TolTurn</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Nicht gespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>TolTurn did not close normally. A copy of %1 with unsaved changes was kept at %2.</source>
        <translation>TolTurn wurde nicht normal beendet. Eine Kopie von %1 mit nicht gespeicherten Änderungen wurde unter %2 aufbewahrt.</translation>
    </message>
    <message>
        <source>Recover it? A discarded copy is deleted.</source>
        <translation>Wiederherstellen? Eine verworfene Kopie wird gelöscht.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Nicht gespeicherte Änderungen</translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation>%1 enthält nicht gespeicherte Änderungen.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>Vor dem Fortfahren speichern?</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>The new language is used when TolTurn is next started.</source>
        <translation>Die neue Sprache wird beim nächsten Start von TolTurn verwendet.</translation>
    </message>
    <message>
        <source>%1 — length %2 %7, Ø max %3 %7, %4 outer / %5 inner features, clamping: %6</source>
        <translation>%1 — Länge %2 %7, Ø max. %3 %7, %4 äußere / %5 innere Formelemente, Spannung: %6</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>&amp;Fit Part</source>
        <translation>&amp;Werkstück einpassen</translation>
    </message>
    <message>
        <source>Show the whole part in the drawing (Ctrl+0, or double-click the drawing)</source>
        <translation>Das ganze Werkstück in der Zeichnung zeigen (Strg+0, oder Doppelklick in die Zeichnung)</translation>
    </message>
    <message>
        <source>&amp;Optimise Cutting Conditions</source>
        <translation>Schnittwerte &amp;optimieren</translation>
    </message>
    <message>
        <source>Find the cutting conditions that hold every tolerance at least time or cost (F5)</source>
        <translation>Die Schnittwerte finden, die jede Toleranz bei geringster Zeit oder geringsten Kosten einhalten (F5)</translation>
    </message>
    <message>
        <source>&amp;Import STEP/IGES…</source>
        <translation>STEP/IGES &amp;importieren…</translation>
    </message>
    <message>
        <source>Read a turned part from a STEP or IGES solid (Ctrl+I)</source>
        <translation>Ein Drehteil aus einem STEP- oder IGES-Körper einlesen (Strg+I)</translation>
    </message>
    <message>
        <source>Export S&amp;TEP…</source>
        <translation>S&amp;TEP exportieren…</translation>
    </message>
    <message>
        <source>Write the part as a solid revolved about its axis (STEP, mm)</source>
        <translation>Das Teil als Rotationskörper um seine Achse schreiben (STEP, mm)</translation>
    </message>
    <message>
        <source>Import Messages</source>
        <translation>Importmeldungen</translation>
    </message>
    <message>
        <source>No STEP or IGES file imported in this session.</source>
        <translation>In dieser Sitzung wurde keine STEP- oder IGES-Datei importiert.</translation>
    </message>
    <message>
        <source>Import STEP or IGES</source>
        <translation>STEP oder IGES importieren</translation>
    </message>
    <message>
        <source>STEP and IGES files (*.step *.stp *.iges *.igs);;All files (*)</source>
        <translation>STEP- und IGES-Dateien (*.step *.stp *.iges *.igs);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Export STEP</source>
        <translation>STEP exportieren</translation>
    </message>
    <message>
        <source>STEP files (*.step *.stp)</source>
        <translation>STEP-Dateien (*.step *.stp)</translation>
    </message>
    <message>
        <source>Planning &amp;Data…</source>
        <translation>Planungs&amp;daten…</translation>
    </message>
    <message>
        <source>Rates, tool life, the insert&apos;s cutting ranges and the part&apos;s limits for the optimiser</source>
        <translation>Kostensätze, Standzeit, Schnittbereiche der Wendeschneidplatte und Grenzwerte des Teils für die Optimierung</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>The user guide, at the page of the dock you are in (F1)</source>
        <translation>Das Benutzerhandbuch, auf der Seite des Fensterbereichs, in dem Sie arbeiten (F1)</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Probleme</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>The set-up shown: its part as held, its deflection, verdicts, plan and program</source>
        <translation>Die angezeigte Aufspannung: ihr Teil wie gespannt, ihre Verformung, Bewertungen, Plan und Programm</translation>
    </message>
    <message>
        <source>%1: %2, %3 end held</source>
        <translation>%1: %2, Ende %3 gespannt</translation>
    </message>
    <message>
        <source>&amp;Operations…</source>
        <translation>&amp;Aufspannungen…</translation>
    </message>
    <message>
        <source>The set-ups the part is turned in and the features each cuts</source>
        <translation>Die Aufspannungen, in denen das Teil gedreht wird, und die Formelemente, die jede bearbeitet</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>E&amp;xtras</translation>
    </message>
    <message>
        <source>Check with &amp;Solid FE…</source>
        <translation>Mit &amp;FE-Volumenmodell prüfen…</translation>
    </message>
    <message>
        <source>Check the beam&apos;s deflection of the part against a solid model meshed with gmsh and solved with CalculiX</source>
        <translation>Die Verformung des Teils im Balkenmodell mit einem Volumenmodell prüfen, vernetzt mit gmsh und gelöst mit CalculiX</translation>
    </message>
    <message>
        <source>Čuš &amp;&amp; Župerl &amp;End-Milling Example…</source>
        <translation>Stirnfräs&amp;beispiel von Čuš &amp;&amp; Župerl…</translation>
    </message>
    <message>
        <source>The constant-force control paper&apos;s own end-milling system rebuilt, beside its results</source>
        <translation>Das eigene Stirnfräs-System des Artikels zur Konstantkraftregelung nachgebaut, neben seinen Ergebnissen</translation>
    </message>
    <message>
        <source>Milling</source>
        <translation>Fräsen</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasuredPartsModel</name>
    <message>
        <source>Part %1</source>
        <translation>Teil %1</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>By</source>
        <translation>Prüfer</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementEntryDialog</name>
    <message>
        <source>Measured Part — %1 on %2</source>
        <translation>Gemessenes Teil — %1 auf %2</translation>
    </message>
    <message>
        <source>micrometer</source>
        <translation>Bügelmessschraube</translation>
    </message>
    <message>
        <source>CMM</source>
        <translation>KMG</translation>
    </message>
    <message>
        <source>bore gauge</source>
        <translation>Innenmessgerät</translation>
    </message>
    <message>
        <source>dial gauge along the part</source>
        <translation>Messuhr entlang des Teils</translation>
    </message>
    <message>
        <source>as in the project</source>
        <translation>wie im Projekt</translation>
    </message>
    <message>
        <source>Minutes from the machine&apos;s start to the cut: the warm-up the thermal error depends on (Li &amp; Du 2022, §3.2).</source>
        <translation>Minuten vom Einschalten der Maschine bis zum Schnitt: die Erwärmung, von der der thermische Fehler abhängt (Li &amp; Du 2022, §3.2).</translation>
    </message>
    <message>
        <source>Measured &amp;by:</source>
        <translation>Gemessen &amp;von:</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Messverfahren:</translation>
    </message>
    <message>
        <source>Measured &amp;at:</source>
        <translation>Gemessen &amp;am:</translation>
    </message>
    <message>
        <source>&amp;Time since start [min]:</source>
        <translation>&amp;Zeit seit Einschalten [min]:</translation>
    </message>
    <message>
        <source>Am&amp;bient [°C]:</source>
        <translation>Umge&amp;bung [°C]:</translation>
    </message>
    <message>
        <source>&amp;Note:</source>
        <translation>&amp;Notiz:</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>One measured point a row: a diameter in mm, or a radial deviation in µm (material left on the surface positive).</source>
        <translation>Ein Messpunkt je Zeile: ein Durchmesser in mm oder eine radiale Abweichung in µm (an der Oberfläche verbliebenes Material positiv).</translation>
    </message>
    <message>
        <source>Add &amp;Row</source>
        <translation>Zeile &amp;hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Remove Rows</source>
        <translation>Zeilen &amp;entfernen</translation>
    </message>
    <message>
        <source>Read &amp;CSV…</source>
        <translation>&amp;CSV lesen…</translation>
    </message>
    <message>
        <source>Columns feature, z_mm and diameter_mm or radial_deviation_um (docs/learning.md).</source>
        <translation>Spalten feature, z_mm und diameter_mm oder radial_deviation_um (docs/learning.md).</translation>
    </message>
    <message>
        <source>&amp;Store</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>diameter [mm]</source>
        <translation>Durchmesser [mm]</translation>
    </message>
    <message>
        <source>radial deviation [µm]</source>
        <translation>radiale Abweichung [µm]</translation>
    </message>
    <message>
        <source>Read Measured Points</source>
        <translation>Messpunkte lesen</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-Dateien (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The file was not read:</source>
        <translation>Die Datei wurde nicht gelesen:</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) read from %1.</source>
        <translation>
            <numerusform>%n Punkt aus %1 gelesen.</numerusform>
            <numerusform>%n Punkte aus %1 gelesen.</numerusform>
        </translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>row %1, %2</source>
        <translation>Zeile %1, %2</translation>
    </message>
    <message>
        <source>CMM point x; y [mm]</source>
        <translation>KMG-Punkt x; y [mm]</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementsPanel</name>
    <message>
        <source>Use the &amp;Local Store</source>
        <translation>&amp;Lokalen Speicher verwenden</translation>
    </message>
    <message>
        <source>Work with the measurement store on this computer until the shop database can be reached again (Preferences keep the shop database).</source>
        <translation>Mit dem Messwertspeicher auf diesem Computer arbeiten, bis die Werkstattdatenbank wieder erreichbar ist (die Einstellungen behalten die Werkstattdatenbank).</translation>
    </message>
    <message>
        <source>This project&apos;s machine</source>
        <translation>Maschine dieses Projekts</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>Alle Maschinen</translation>
    </message>
    <message>
        <source>Filter by part, who measured or method</source>
        <translation>Nach Teil, Prüfer oder Verfahren filtern</translation>
    </message>
    <message>
        <source>&amp;Add Measured Part…</source>
        <translation>Gemessenes Teil &amp;hinzufügen…</translation>
    </message>
    <message>
        <source>Type in (or read from CSV) the measured points of a part cut from the open project.</source>
        <translation>Die Messpunkte eines nach dem geöffneten Projekt gefertigten Teils eingeben (oder aus CSV lesen).</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>CSV e&amp;xportieren…</translation>
    </message>
    <message>
        <source>What was learned of the machine</source>
        <translation>Was von der Maschine gelernt wurde</translation>
    </message>
    <message>
        <source>L&amp;earn</source>
        <translation>Ler&amp;nen</translation>
    </message>
    <message>
        <source>Learn the machine&apos;s error beyond the physics from all its measured parts (Li &amp; Du 2022: geometric error by regression, the rest by a hybrid RBF network), check it by leaving one part out, and keep it.</source>
        <translation>Den Fehler der Maschine über die Physik hinaus aus allen ihren gemessenen Teilen lernen (Li &amp; Du 2022: geometrischer Fehler per Regression, der Rest mit einem hybriden RBF-Netz), ihn durch Weglassen je eines Teils prüfen und behalten.</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>&amp;Use in the predictions (verdicts, curves, plan, program, report)</source>
        <translation>In den Vorhersagen &amp;verwenden (Bewertungen, Kurven, Plan, Programm, Bericht)</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Maschine %1</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <source>of %1</source>
        <translation>von %1</translation>
    </message>
    <message>
        <source>of all machines</source>
        <translation>aller Maschinen</translation>
    </message>
    <message numerus="yes">
        <source>%n measured part(s) %1 in %2</source>
        <translation>
            <numerusform>%n gemessenes Teil %1 in %2</numerusform>
            <numerusform>%n gemessene Teile %1 in %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Open a project to learn its machine from the parts measured on it.</source>
        <translation>Öffnen Sie ein Projekt, um dessen Maschine aus den darauf gefertigten und gemessenen Teilen zu lernen.</translation>
    </message>
    <message>
        <source>Nothing has been learned of %1 yet. Learn needs at least two measured parts; the more parts, conditions and times of day they cover, the better.</source>
        <translation>Von %1 wurde noch nichts gelernt. Lernen braucht mindestens zwei gemessene Teile; je mehr Teile, Bedingungen und Tageszeiten sie abdecken, desto besser.</translation>
    </message>
    <message>
        <source>Model %1, learned %2 from %3 parts (%4 points). Parts not learned from (leave one part out): physics alone %5 µm RMS, physics + learned %6 µm RMS.</source>
        <translation>Modell %1, gelernt %2 aus %3 Teilen (%4 Punkte). Nicht gelernte Teile (ein Teil weggelassen): Physik allein %5 µm RMS, Physik + Gelerntes %6 µm RMS.</translation>
    </message>
    <message numerus="yes">
        <source>Part %1 stored with %n point(s).</source>
        <translation>
            <numerusform>Teil %1 mit %n Punkt gespeichert.</numerusform>
            <numerusform>Teil %1 mit %n Punkten gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Measured Part Not Stored</source>
        <translation>Gemessenes Teil nicht gespeichert</translation>
    </message>
    <message>
        <source>Remove Measured Parts</source>
        <translation>Gemessene Teile entfernen</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n measured part(s) and their points from %1? Models learned before keep what they learned.</source>
        <translation>
            <numerusform>%n gemessenes Teil und seine Punkte aus %1 entfernen? Zuvor gelernte Modelle behalten, was sie gelernt haben.</numerusform>
            <numerusform>%n gemessene Teile und ihre Punkte aus %1 entfernen? Zuvor gelernte Modelle behalten, was sie gelernt haben.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) removed.</source>
        <translation>
            <numerusform>%n Teil entfernt.</numerusform>
            <numerusform>%n Teile entfernt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not Removed</source>
        <translation>Nicht entfernt</translation>
    </message>
    <message>
        <source>Export Measured Parts</source>
        <translation>Gemessene Teile exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) written to %1.</source>
        <translation>
            <numerusform>%n Teil nach %1 geschrieben.</numerusform>
            <numerusform>%n Teile nach %1 geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not Exported</source>
        <translation>Nicht exportiert</translation>
    </message>
    <message>
        <source>Learning %1 from its measured parts…</source>
        <translation>%1 wird aus ihren gemessenen Teilen gelernt…</translation>
    </message>
    <message>
        <source>Learned and kept as model %1.</source>
        <translation>Gelernt und als Modell %1 behalten.</translation>
    </message>
    <message>
        <source>Learning cancelled; the model before is kept.</source>
        <translation>Lernen abgebrochen; das bisherige Modell bleibt erhalten.</translation>
    </message>
    <message>
        <source>Nothing learned: %1</source>
        <translation>Nichts gelernt: %1</translation>
    </message>
    <message>
        <source>Part %1: measured and predicted radius error</source>
        <translation>Teil %1: gemessener und vorhergesagter Radiusfehler</translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [%1]</source>
        <translation>z vom linken Teilende [%1]</translation>
    </message>
    <message>
        <source>machined − programmed radius [%1]</source>
        <translation>gefertigter − programmierter Radius [%1]</translation>
    </message>
    <message>
        <source>physics</source>
        <translation>Physik</translation>
    </message>
    <message>
        <source>physics + learned − %1 µm</source>
        <translation>Physik + Gelerntes − %1 µm</translation>
    </message>
    <message>
        <source>physics + learned + %1 µm</source>
        <translation>Physik + Gelerntes + %1 µm</translation>
    </message>
    <message>
        <source>physics + learned</source>
        <translation>Physik + Gelerntes</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message numerus="yes">
        <source>Measured %1 by %2 (%3), %n point(s) compared.</source>
        <translation>
            <numerusform>Gemessen %1 von %2 (%3), %n Punkt verglichen.</numerusform>
            <numerusform>Gemessen %1 von %2 (%3), %n Punkte verglichen.</numerusform>
        </translation>
    </message>
    <message>
        <source>No model of %1 to compare with: Learn, then select the part again.</source>
        <translation>Kein Modell von %1 zum Vergleichen: „Lernen“ ausführen, dann das Teil erneut auswählen.</translation>
    </message>
    <message>
        <source>the store or the machine changed meanwhile; the model was kept in %1</source>
        <translation>Speicher oder Maschine haben sich inzwischen geändert; das Modell wurde in %1 gespeichert</translation>
    </message>
    <message>
        <source>Learned at %1.</source>
        <translation>Gelernt bei %1.</translation>
    </message>
</context>
<context>
    <name>tolturn::MilledFeaturesBox</name>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>flatness</source>
        <translation>Ebenheit</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <source>not evaluated: lacks %1</source>
        <translation>nicht ausgewertet, es fehlt: %1</translation>
    </message>
    <message>
        <source>not evaluated: %1</source>
        <translation>nicht ausgewertet: %1</translation>
    </message>
    <message>
        <source>passes, %1 of %2 µm</source>
        <translation>besteht, %1 von %2 µm</translation>
    </message>
    <message>
        <source>fails, %1 of %2 µm</source>
        <translation>verfehlt, %1 von %2 µm</translation>
    </message>
    <message>
        <source>Milled features of the part</source>
        <translation>Gefräste Formelemente des Teils</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>where the cutting coefficients come from</source>
        <translation>Herkunft der Schnittkraftkoeffizienten</translation>
    </message>
    <message>
        <source>Add Cut as Feature</source>
        <translation>Schnitt als Formelement hinzufügen</translation>
    </message>
    <message>
        <source>Save Cut to Feature</source>
        <translation>Schnitt im Formelement speichern</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>z from, to</source>
        <translation>z von, bis</translation>
    </message>
    <message>
        <source>Coefficients from</source>
        <translation>Koeffizienten aus</translation>
    </message>
    <message>
        <source>along the path [mm]</source>
        <translation>entlang der Bahn [mm]</translation>
    </message>
    <message>
        <source>surface-normal error [µm]</source>
        <translation>Abweichung entlang der Flächennormalen [µm]</translation>
    </message>
    <message>
        <source>evaluating…</source>
        <translation>wird ausgewertet…</translation>
    </message>
    <message>
        <source>Choose an evaluated feature</source>
        <translation>Wählen Sie ein ausgewertetes Formelement</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>δ_N least</source>
        <translation>δ_N kleinstes</translation>
    </message>
    <message>
        <source>δ_N over a revolution</source>
        <translation>δ_N über eine Umdrehung</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>Zone, unten</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>Zone, oben</translation>
    </message>
    <message>
        <source>Add milled feature %1</source>
        <translation>Gefrästes Formelement %1 hinzufügen</translation>
    </message>
    <message>
        <source>Choose the feature to save the cut to.</source>
        <translation>Wählen Sie das Formelement, in dem der Schnitt gespeichert werden soll.</translation>
    </message>
    <message>
        <source>Change milled feature %1</source>
        <translation>Gefrästes Formelement %1 ändern</translation>
    </message>
    <message>
        <source>Choose the feature to remove.</source>
        <translation>Wählen Sie das zu entfernende Formelement.</translation>
    </message>
    <message>
        <source>Remove milled feature %1</source>
        <translation>Gefrästes Formelement %1 entfernen</translation>
    </message>
    <message>
        <source>Evaluating…</source>
        <translation>Wird bewertet…</translation>
    </message>
    <message>
        <source>Coefficients from: &quot;%1&quot; is given but there are no coefficients (Ktc, Krc, Kac, Kte, Kre, Kae) to go with it; enter them, or clear the field.</source>
        <translation>Koeffizienten aus: „%1“ ist angegeben, aber es gibt keine Koeffizienten (Ktc, Krc, Kac, Kte, Kre, Kae) dazu; geben Sie sie ein oder leeren Sie das Feld.</translation>
    </message>
</context>
<context>
    <name>tolturn::MillingPanel</name>
    <message>
        <source>Ball-end cut</source>
        <translation>Kugelkopfschnitt</translation>
    </message>
    <message>
        <source>Öztürk &amp; Budak, case %1</source>
        <translation>Öztürk &amp; Budak, Fall %1</translation>
    </message>
    <message>
        <source>Own cut</source>
        <translation>Eigener Schnitt</translation>
    </message>
    <message>
        <source>001 table 4: a DMU 50 Evolution, Ø12 mm ball-end mills with a 30° helix, Ti6Al4V</source>
        <translation>001 Tabelle 4: eine DMU 50 Evolution, Kugelkopffräser Ø12 mm mit 30° Drall, Ti6Al4V</translation>
    </message>
    <message>
        <source>Example</source>
        <translation>Beispiel</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>Nut</translation>
    </message>
    <message>
        <source>Side cut (uncut material)</source>
        <translation>Seitlicher Schnitt (unbearbeitetes Material)</translation>
    </message>
    <message>
        <source>Step-over (beside a pass)</source>
        <translation>Bahnabstand (neben einer Bahn)</translation>
    </message>
    <message>
        <source>Down milling</source>
        <translation>Gleichlauffräsen</translation>
    </message>
    <message>
        <source>Up milling</source>
        <translation>Gegenlauffräsen</translation>
    </message>
    <message>
        <source> 1/min</source>
        <translation> 1/min</translation>
    </message>
    <message>
        <source>Ktc, Krc, Kac (N/mm²), Kte, Kre, Kae (N/mm)</source>
        <translation>Ktc, Krc, Kac (N/mm²), Kte, Kre, Kae (N/mm)</translation>
    </message>
    <message>
        <source>The cutting and edge coefficients of your tool and material (001 eq. 11). 001 prints none, and TolTurn&apos;s data library has none for ball-end milling.</source>
        <translation>Die Schnitt- und Kantenkoeffizienten Ihres Werkzeugs und Werkstoffs (001 Gl. 11). 001 druckt keine, und TolTurns Datenbibliothek hat keine für das Kugelkopffräsen.</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation>Schneiden</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Drall</translation>
    </message>
    <message>
        <source>Lead</source>
        <translation>Anstellwinkel</translation>
    </message>
    <message>
        <source>Tilt</source>
        <translation>Kippwinkel</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Radial depth / step-over</source>
        <translation>Radiale Zustellung / Bahnabstand</translation>
    </message>
    <message>
        <source>Axial depth</source>
        <translation>Axiale Zustellung</translation>
    </message>
    <message>
        <source>Feed per tooth</source>
        <translation>Vorschub je Zahn</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Spindeldrehzahl</translation>
    </message>
    <message>
        <source>Coefficients</source>
        <translation>Koeffizienten</translation>
    </message>
    <message>
        <source>Tool structure and tolerance</source>
        <translation>Werkzeugaufbau und Toleranz</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>From where the holder grips the tool to its tip</source>
        <translation>Von der Einspannung im Halter bis zur Werkzeugspitze</translation>
    </message>
    <message>
        <source>The diameter of the solid cylinder that bends like the fluted tool</source>
        <translation>Der Durchmesser des Vollzylinders, der sich wie das genutete Werkzeug biegt</translation>
    </message>
    <message>
        <source> N/mm²</source>
        <translation> N/mm²</translation>
    </message>
    <message>
        <source>Tungsten carbide 630 000 N/mm² (MakeItFrom); cemented carbides 530 000–700 000</source>
        <translation>Wolframkarbid 630 000 N/mm² (MakeItFrom); Hartmetalle 530 000–700 000</translation>
    </message>
    <message>
        <source> N/mm</source>
        <translation> N/mm</translation>
    </message>
    <message>
        <source> N·mm/rad</source>
        <translation> N·mm/rad</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> µm</translation>
    </message>
    <message>
        <source>Profile with datums (±t/2)</source>
        <translation>Profil mit Bezügen (±t/2)</translation>
    </message>
    <message>
        <source>The largest feed per tooth the tool&apos;s maker allows</source>
        <translation>Der größte Vorschub je Zahn, den der Werkzeughersteller zulässt</translation>
    </message>
    <message>
        <source>Plan Lead, Tilt and Feed</source>
        <translation>Anstellwinkel, Kippwinkel und Vorschub planen</translation>
    </message>
    <message>
        <source>Overhang</source>
        <translation>Auskraglänge</translation>
    </message>
    <message>
        <source>Equivalent diameter</source>
        <translation>Ersatzdurchmesser</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>Elastizitätsmodul</translation>
    </message>
    <message>
        <source>Holder k</source>
        <translation>Halter k</translation>
    </message>
    <message>
        <source>Holder k_θ</source>
        <translation>Halter k_θ</translation>
    </message>
    <message>
        <source>Surface tolerance t</source>
        <translation>Flächentoleranz t</translation>
    </message>
    <message>
        <source>Zone</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>Largest feed per tooth</source>
        <translation>Größter Vorschub je Zahn</translation>
    </message>
    <message>
        <source>Holder springs: as entered.</source>
        <translation>Halterfedern: wie eingegeben.</translation>
    </message>
    <message>
        <source>rotation angle [°]</source>
        <translation>Drehwinkel [°]</translation>
    </message>
    <message>
        <source>force on the tool [N]</source>
        <translation>Kraft am Werkzeug [N]</translation>
    </message>
    <message>
        <source>surface-normal error [µm]</source>
        <translation>Abweichung entlang der Flächennormalen [µm]</translation>
    </message>
    <message>
        <source>lead [°]</source>
        <translation>Anstellwinkel [°]</translation>
    </message>
    <message>
        <source>tilt [°]</source>
        <translation>Kippwinkel [°]</translation>
    </message>
    <message>
        <source>Plan to see the largest feed per tooth that holds the tolerance at each lead and tilt.</source>
        <translation>Planen zeigt den größten Vorschub je Zahn, der die Toleranz bei jedem Anstell- und Kippwinkel hält.</translation>
    </message>
    <message>
        <source>Forces</source>
        <translation>Kräfte</translation>
    </message>
    <message>
        <source>Surface error</source>
        <translation>Flächenabweichung</translation>
    </message>
    <message>
        <source>Lead–tilt window</source>
        <translation>Anstell-Kipp-Fenster</translation>
    </message>
    <message>
        <source>Holder springs: 001&apos;s calibration for its Ø12 mm tool and holder, under 1000 N.</source>
        <translation>Halterfedern: Kalibrierung aus 001 für dessen Werkzeug Ø12 mm und Halter, unter 1000 N.</translation>
    </message>
    <message>
        <source>Coefficients: not given. Enter Ktc, Krc, Kac, Kte, Kre, Kae of your tool and material: Öztürk &amp; Budak print none (theirs come from a Ti6Al4V orthogonal-cutting database), and TolTurn&apos;s data library has none for ball-end milling.</source>
        <translation>Koeffizienten: nicht angegeben. Geben Sie Ktc, Krc, Kac, Kte, Kre, Kae Ihres Werkzeugs und Werkstoffs ein: Öztürk &amp; Budak drucken keine (ihre stammen aus einer Orthogonalschnitt-Datenbank für Ti6Al4V), und TolTurns Datenbibliothek hat keine für das Kugelkopffräsen.</translation>
    </message>
    <message>
        <source>Coefficients: &quot;%1&quot; is not six numbers of at most 100 000.</source>
        <translation>Koeffizienten: „%1“ sind nicht sechs Zahlen von höchstens 100 000.</translation>
    </message>
    <message>
        <source>No surface error: %1</source>
        <translation>Keine Flächenabweichung: %1</translation>
    </message>
    <message>
        <source>F (feed)</source>
        <translation>F (Vorschub)</translation>
    </message>
    <message>
        <source>C (cross-feed)</source>
        <translation>C (quer zum Vorschub)</translation>
    </message>
    <message>
        <source>N (normal)</source>
        <translation>N (Normale)</translation>
    </message>
    <message>
        <source>resultant</source>
        <translation>Resultierende</translation>
    </message>
    <message>
        <source>Peak resultant %1 N; mean torque %2 N·m, mean spindle power %3 W. Coefficients as entered; only the tool deflects (001 §4).</source>
        <translation>Größte Resultierende %1 N; mittleres Drehmoment %2 N·m, mittlere Spindelleistung %3 W. Koeffizienten wie eingegeben; nur das Werkzeug biegt sich (001 §4).</translation>
    </message>
    <message>
        <source>δ_N</source>
        <translation>δ_N</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>Zone, unten</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>Zone, oben</translation>
    </message>
    <message>
        <source>&lt;b&gt;passes&lt;/b&gt; by %1 µm</source>
        <translation>&lt;b&gt;besteht&lt;/b&gt; mit %1 µm</translation>
    </message>
    <message>
        <source>&lt;b&gt;fails&lt;/b&gt; by %1 µm</source>
        <translation>&lt;b&gt;verfehlt&lt;/b&gt; um %1 µm</translation>
    </message>
    <message>
        <source>&lt;br&gt;Surface-normal error %1 to %2 µm over a revolution; against t = %3 µm (%4) it %5.</source>
        <translation>&lt;br&gt;Abweichung entlang der Flächennormalen %1 bis %2 µm über eine Umdrehung; gegen t = %3 µm (%4): %5.</translation>
    </message>
    <message>
        <source>spread</source>
        <translation>Spanne</translation>
    </message>
    <message>
        <source>±t/2</source>
        <translation>±t/2</translation>
    </message>
    <message>
        <source>Planning: 64 × 64 leads and tilts…</source>
        <translation>Planung: 64 × 64 Anstell- und Kippwinkel…</translation>
    </message>
    <message>
        <source>plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <source>as entered</source>
        <translation>wie eingegeben</translation>
    </message>
    <message>
        <source>Lighter: a larger feed per tooth holds the tolerance; red: none does; grey: the cut would reach the shank above the ball.</source>
        <translation>Heller: ein größerer Vorschub je Zahn hält die Toleranz; rot: keiner; grau: der Schnitt erreichte den Schaft über der Kugel.</translation>
    </message>
    <message>
        <source>Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min), form error %5 µm. %6</source>
        <translation>Plan: Anstellwinkel %1°, Kippwinkel %2°, Vorschub %3 mm/Zahn (%4 mm/min), Formabweichung %5 µm. %6</translation>
    </message>
    <message>
        <source>No lead and tilt within ±40° holds the tolerance at any feed. %1</source>
        <translation>Kein Anstell- und Kippwinkel innerhalb ±40° hält die Toleranz bei irgendeinem Vorschub. %1</translation>
    </message>
    <message>
        <source>give the tool&apos;s overhang</source>
        <translation>geben Sie die Auskraglänge des Werkzeugs an</translation>
    </message>
    <message>
        <source>give the tool&apos;s equivalent diameter</source>
        <translation>geben Sie den Ersatzdurchmesser des Werkzeugs an</translation>
    </message>
    <message>
        <source>No plan: %1</source>
        <translation>Kein Plan: %1</translation>
    </message>
    <message>
        <source>The inputs have changed since this plan: plan again.</source>
        <translation>Die Eingaben haben sich seit diesem Plan geändert: erneut planen.</translation>
    </message>
    <message>
        <source>Flatness</source>
        <translation>Ebenheit</translation>
    </message>
    <message>
        <source>Profile without datums</source>
        <translation>Profil ohne Bezüge</translation>
    </message>
    <message>
        <source>ISO 1101: a flatness and a profile without datums float (the spread within t); a profile with datums is located on the programmed surface (within ±t/2)</source>
        <translation>ISO 1101: Ebenheit und Profil ohne Bezüge sind schwebend (die Spanne innerhalb t); ein Profil mit Bezügen liegt fest auf der programmierten Fläche (innerhalb ±t/2)</translation>
    </message>
    <message>
        <source>Along the path</source>
        <translation>Entlang der Bahn</translation>
    </message>
    <message>
        <source>Holder springs: feature %1&apos;s.</source>
        <translation>Halterfedern: aus Formelement %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 lacks %2&lt;/b&gt;: the fields show the last cut; save the cut to the feature to give it these.</source>
        <translation>&lt;b&gt;Für %1 fehlt: %2&lt;/b&gt; – die Felder zeigen den letzten Schnitt; speichern Sie den Schnitt im Formelement, um ihm diese Werte zu geben.</translation>
    </message>
    <message>
        <source>&lt;br&gt;A patch&apos;s lead and tilt come from its path, point by point (Along the path); the fields show its conditions&apos; own.</source>
        <translation>&lt;br&gt;Anstell- und Kippwinkel einer Freiformfläche ergeben sich Punkt für Punkt aus ihrer Bahn (Entlang der Bahn); die Felder zeigen die eigenen Werte ihrer Schnittbedingungen.</translation>
    </message>
    <message>
        <source>A, B</source>
        <translation>A, B</translation>
    </message>
    <message>
        <source>Datums</source>
        <translation>Bezüge</translation>
    </message>
    <message>
        <source>Feature %1 has no holder springs: these are the last cut&apos;s, and saving the cut gives them to it.</source>
        <translation>Formelement %1 hat keine Halterfedern: dies sind die des letzten Schnitts, und Speichern des Schnitts gibt sie ihm.</translation>
    </message>
    <message>
        <source>Coefficients: &quot;%1&quot; is not six numbers; the feature is left as it was.</source>
        <translation>Koeffizienten: „%1“ sind nicht sechs Zahlen; das Formelement bleibt, wie es war.</translation>
    </message>
    <message>
        <source>A profile with datums needs its datums (A, B).</source>
        <translation>Ein Profil mit Bezügen braucht seine Bezüge (A, B).</translation>
    </message>
    <message>
        <source>Beyond 001:</source>
        <translation>Außerhalb von 001:</translation>
    </message>
    <message>
        <source>Beyond 001: %1</source>
        <translation>Außerhalb von 001: %1</translation>
    </message>
</context>
<context>
    <name>tolturn::OperationsDialog</name>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>Operations</source>
        <translation>Aufspannungen</translation>
    </message>
    <message>
        <source>&amp;Add Operation</source>
        <translation>Aufspannung &amp;hinzufügen</translation>
    </message>
    <message>
        <source>A set-up after the others: the part turned end for end in the chuck, with this project&apos;s tool and passes; tick the features it cuts</source>
        <translation>Eine Aufspannung nach den anderen: das Teil umgedreht im Spannfutter, mit Werkzeug und Schnitten dieses Projekts; die Formelemente ankreuzen, die sie bearbeitet</translation>
    </message>
    <message>
        <source>Set-ups, in order:</source>
        <translation>Aufspannungen, der Reihe nach:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>Features it cuts (the first set-up cuts every feature no other ticks):</source>
        <translation>Formelemente, die sie bearbeitet (die erste Aufspannung bearbeitet jedes, das keine andere ankreuzt):</translation>
    </message>
    <message>
        <source>Clamping, tools and passes of each set-up are edited in the Set-up dock with the set-up chosen in the toolbar (docs/operations.md).</source>
        <translation>Spannung, Werkzeuge und Schnitte jeder Aufspannung werden im Einrichten-Fenster bearbeitet, mit der in der Werkzeugleiste gewählten Aufspannung (docs/operations.md).</translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningDataDialog</name>
    <message>
        <source>Planning Data</source>
        <translation>Planungsdaten</translation>
    </message>
    <message>
        <source>What the optimiser works with (docs/planning.md). A box showing “—” is not given.</source>
        <translation>Womit die Optimierung rechnet (docs/planning.md). Ein Feld mit „—“ ist nicht angegeben.</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Rates and times</source>
        <translation>Kostensätze und Zeiten</translation>
    </message>
    <message>
        <source>Cost per part C = M·t + C_edge·edges (docs/planning.md §1); in the currency of your choice, the same for both rates.</source>
        <translation>Kosten je Teil C = M·t + C_edge·Schneiden (docs/planning.md §1); in einer Währung Ihrer Wahl, für beide Sätze dieselbe.</translation>
    </message>
    <message>
        <source>&amp;Machine and operator rate:</source>
        <translation>&amp;Maschinen- und Bedienersatz:</translation>
    </message>
    <message>
        <source>per min</source>
        <translation>je min</translation>
    </message>
    <message>
        <source>Tool cost per &amp;edge:</source>
        <translation>Werkzeugkosten je &amp;Schneide:</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>Time to index or change the cutting edge, t_change (docs/planning.md §1).</source>
        <translation>Zeit zum Drehen oder Wechseln der Schneide, t_change (docs/planning.md §1).</translation>
    </message>
    <message>
        <source>&amp;Handling time per part:</source>
        <translation>&amp;Nebenzeit je Teil:</translation>
    </message>
    <message>
        <source>Loading, unloading and idle moves per part, t_handling (docs/planning.md §1).</source>
        <translation>Be- und Entladen und Leerwege je Teil, t_handling (docs/planning.md §1).</translation>
    </message>
    <message>
        <source>Tool life (Taylor: v·Tⁿ = C)</source>
        <translation>Standzeit (Taylor: v·Tⁿ = C)</translation>
    </message>
    <message>
        <source>Taylor (1907): v·Tⁿ = C with v in m/min and T in min; give both C and n, from the insert maker or your own tool-life tests, with their source. Without them tool life is left out of the plan.</source>
        <translation>Taylor (1907): v·Tⁿ = C mit v in m/min und T in min; C und n zusammen angeben, vom Plattenhersteller oder aus eigenen Standzeitversuchen, mit Quelle. Ohne sie bleibt die Standzeit im Plan unberücksichtigt.</translation>
    </message>
    <message>
        <source>&amp;C:</source>
        <translation>&amp;C:</translation>
    </message>
    <message>
        <source>m/min</source>
        <translation>m/min</translation>
    </message>
    <message>
        <source>&amp;n:</source>
        <translation>&amp;n:</translation>
    </message>
    <message>
        <source>Minimum tool &amp;life:</source>
        <translation>Mindest&amp;standzeit:</translation>
    </message>
    <message>
        <source>The tool_life constraint: T(v) at least this (docs/planning.md §2).</source>
        <translation>Die Nebenbedingung tool_life: T(v) mindestens dieser Wert (docs/planning.md §2).</translation>
    </message>
    <message>
        <source>where C and n come from</source>
        <translation>woher C und n stammen</translation>
    </message>
    <message>
        <source>&amp;Source:</source>
        <translation>&amp;Quelle:</translation>
    </message>
    <message>
        <source>From the Material&apos;s Data</source>
        <translation>Aus den Werkstoffdaten</translation>
    </message>
    <message>
        <source>Fill C, n and the source from the data of %1.</source>
        <translation>C, n und Quelle aus den Daten von %1 übernehmen.</translation>
    </message>
    <message>
        <source>The data of %1 gives no Taylor constants.</source>
        <translation>Die Daten von %1 enthalten keine Taylor-Konstanten.</translation>
    </message>
    <message>
        <source>%1 (material %2): C from %3; n from %4</source>
        <translation>%1 (Werkstoff %2): C aus %3; n aus %4</translation>
    </message>
    <message>
        <source>TolTurn material data</source>
        <translation>TolTurn-Werkstoffdaten</translation>
    </message>
    <message>
        <source>Cutting ranges of the insert</source>
        <translation>Schnittbereiche der Wendeschneidplatte</translation>
    </message>
    <message>
        <source>The insert maker&apos;s recommended range (catalogue), the bounds of the optimiser&apos;s variables (docs/planning.md §2–3).</source>
        <translation>Der vom Plattenhersteller empfohlene Bereich (Katalog), die Grenzen der Optimierungsvariablen (docs/planning.md §2–3).</translation>
    </message>
    <message>
        <source>&amp;Feed:</source>
        <translation>&amp;Vorschub:</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/U</translation>
    </message>
    <message>
        <source>&amp;Depth of cut:</source>
        <translation>Schnitt&amp;tiefe:</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>catalogue, page, chip breaker</source>
        <translation>Katalog, Seite, Spanformer</translation>
    </message>
    <message>
        <source>S&amp;ource:</source>
        <translation>Q&amp;uelle:</translation>
    </message>
    <message>
        <source>Requirements and limits</source>
        <translation>Anforderungen und Grenzwerte</translation>
    </message>
    <message>
        <source> “—”: the machine&apos;s limit from its data, if it has one.</source>
        <translation> „—“: die Grenze der Maschine aus ihren Daten, falls vorhanden.</translation>
    </message>
    <message>
        <source>Max. &amp;Ra:</source>
        <translation>Max. &amp;Ra:</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>Theoretical roughness Ra = f²/(32·rε) of the finishing pass.</source>
        <translation>Theoretische Rauheit Ra = f²/(32·rε) des Schlichtschnitts.</translation>
    </message>
    <message>
        <source>Max. R&amp;z:</source>
        <translation>Max. R&amp;z:</translation>
    </message>
    <message>
        <source>Theoretical roughness Rz = f²/(8·rε) of the finishing pass.</source>
        <translation>Theoretische Rauheit Rz = f²/(8·rε) des Schlichtschnitts.</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>Upper limit of the cutting force F_c.</source>
        <translation>Obergrenze der Schnittkraft F_c.</translation>
    </message>
    <message>
        <source>kW</source>
        <translation>kW</translation>
    </message>
    <message>
        <source>Spindle power F_c·v available.</source>
        <translation>Verfügbare Spindelleistung F_c·v.</translation>
    </message>
    <message>
        <source>N·m</source>
        <translation>N·m</translation>
    </message>
    <message>
        <source>Spindle torque F_c·D/2 available.</source>
        <translation>Verfügbares Spindeldrehmoment F_c·D/2.</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>1/min</translation>
    </message>
    <message>
        <source>Tool change &amp;time:</source>
        <translation>Werkzeug&amp;wechselzeit:</translation>
    </message>
    <message>
        <source>Cutting s&amp;peed:</source>
        <translation>Schnitt&amp;geschwindigkeit:</translation>
    </message>
    <message>
        <source>Ma&amp;x. cutting force:</source>
        <translation>Max. Schnitt&amp;kraft:</translation>
    </message>
    <message>
        <source>Max. po&amp;wer:</source>
        <translation>Max. &amp;Leistung:</translation>
    </message>
    <message>
        <source>Max. tor&amp;que:</source>
        <translation>Max. &amp;Drehmoment:</translation>
    </message>
    <message>
        <source>Max. sp&amp;indle speed:</source>
        <translation>Max. S&amp;pindeldrehzahl:</translation>
    </message>
    <message>
        <source>Derive C</source>
        <translation>C ableiten</translation>
    </message>
    <message>
        <source>The speed the insert&apos;s catalogue recommends and the tool life it states for it (often 15 min): C = v·Tⁿ, with n from tool makers&apos; speed–life factors.</source>
        <translation>Die Schnittgeschwindigkeit, die der Katalog der Wendeschneidplatte empfiehlt, und die Standzeit, die er dafür angibt (oft 15 min): C = v·Tⁿ, mit n aus den Standzeitfaktoren der Werkzeughersteller.</translation>
    </message>
    <message>
        <source>at</source>
        <translation>bei</translation>
    </message>
    <message>
        <source>Catalogue speed:</source>
        <translation>Katalog-Schnittgeschwindigkeit:</translation>
    </message>
    <message>
        <source>Catalogue speed: give the recommended speed and the tool life the catalogue states for it.</source>
        <translation>Katalog-Schnittgeschwindigkeit: geben Sie die empfohlene Schnittgeschwindigkeit und die Standzeit an, die der Katalog dafür nennt.</translation>
    </message>
    <message>
        <source>C = %1 m/min x %2 min^%3 from the insert catalogue&apos;s recommended speed; n: %4</source>
        <translation>C = %1 m/min x %2 min^%3 aus der empfohlenen Schnittgeschwindigkeit des Plattenkatalogs; n: %4</translation>
    </message>
    <message>
        <source>Highest spindle speed: the program clamps constant surface speed at it.</source>
        <translation>Höchste Spindeldrehzahl: das Programm begrenzt die konstante Schnittgeschwindigkeit darauf.</translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningPanel</name>
    <message>
        <source>Optimise</source>
        <translation>Optimieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Apply to Passes</source>
        <translation>Auf Schnitte anwenden</translation>
    </message>
    <message>
        <source>Compensated</source>
        <translation>Kompensiert</translation>
    </message>
    <message>
        <source>Export G-code…</source>
        <translation>G-Code exportieren…</translation>
    </message>
    <message>
        <source>Least time per part</source>
        <translation>Minimale Zeit je Teil</translation>
    </message>
    <message>
        <source>Least cost per part</source>
        <translation>Minimale Kosten je Teil</translation>
    </message>
    <message>
        <source>Window: feed – cutting speed</source>
        <translation>Fenster: Vorschub – Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>Window: feed – depth of cut</source>
        <translation>Fenster: Vorschub – Schnitttiefe</translation>
    </message>
    <message>
        <source>Constraints:</source>
        <translation>Randbedingungen:</translation>
    </message>
    <message>
        <source>Switch the %1 constraint on or off (docs/planning.md §2)</source>
        <translation>Randbedingung %1 ein- oder ausschalten (docs/planning.md §2)</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>Rang</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Aufspannung</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Toleranzen</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Maßnahme</translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation>Korrektur Ø [µm]</translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation>Restabweichung vorher [µm]</translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation>Restabweichung nachher [µm]</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <source>Cutting Window</source>
        <translation>Schnittwertfenster</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>Kompensation</translation>
    </message>
    <message>
        <source>G-code</source>
        <translation>G-Code</translation>
    </message>
    <message>
        <source>Export G-code</source>
        <translation>G-Code exportieren</translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.tap);;All files (*)</source>
        <translation>G-Code (*.nc *.ngc *.tap);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Apply optimal passes</source>
        <translation>Optimale Schnitte übernehmen</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Optimal plan</source>
        <translation>Optimaler Plan</translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one:</source>
        <translation>Kein Plan erfüllt alle Randbedingungen; der Plan mit der geringsten Verletzung:</translation>
    </message>
    <message>
        <source>Finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>Schlichten: vc %1 m/min, f %2 mm/rev, ap %3 mm</translation>
    </message>
    <message>
        <source>Binding: %1 (%2 of %3 %4)</source>
        <translation>Begrenzend: %1 (%2 von %3 %4)</translation>
    </message>
    <message>
        <source>Note: </source>
        <translation>Hinweis: </translation>
    </message>
    <message>
        <source>&lt;b&gt;Green&lt;/b&gt;: feasible, darker is better.</source>
        <translation>&lt;b&gt;Grün&lt;/b&gt;: zulässig, dunkler ist besser.</translation>
    </message>
    <message>
        <source>optimum</source>
        <translation>Optimum</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – cutting speed</source>
        <translation>Schnittwertfenster des Schlichtschnitts: Vorschub – Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – depth of cut</source>
        <translation>Schnittwertfenster des Schlichtschnitts: Vorschub – Schnitttiefe</translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation>Vorschub f [mm/rev]</translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation>Schnittgeschwindigkeit vc [m/min]</translation>
    </message>
    <message>
        <source>depth of cut ap [mm]</source>
        <translation>Schnitttiefe ap [mm]</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>constant offset</source>
        <translation>konstante Korrektur</translation>
    </message>
    <message>
        <source>profile correction</source>
        <translation>Konturkorrektur</translation>
    </message>
    <message>
        <source>Planning Data…</source>
        <translation>Planungsdaten…</translation>
    </message>
    <message>
        <source>Rates, tool life, the insert&apos;s cutting ranges and the part&apos;s limits the optimiser works with</source>
        <translation>Kostensätze, Standzeit, Schnittbereiche der Platte und Grenzwerte des Teils, mit denen die Optimierung rechnet</translation>
    </message>
    <message>
        <source>%1: no limit known</source>
        <translation>%1: keine Grenze bekannt</translation>
    </message>
    <message>
        <source>No %1 limit is known for this machine and project: it is not checked. Enter one in Planning Data….</source>
        <translation>Für diese Maschine und dieses Projekt ist keine Grenze für %1 bekannt: sie wird nicht geprüft. Geben Sie eine unter Planungsdaten… ein.</translation>
    </message>
    <message>
        <source>Machine&apos;s control</source>
        <translation>Steuerung der Maschine</translation>
    </message>
    <message>
        <source>The control the program is written for</source>
        <translation>Die Steuerung, für die das Programm geschrieben wird</translation>
    </message>
    <message>
        <source>Nose radius: G41/G42 by the control</source>
        <translation>Eckenradius: G41/G42 durch die Steuerung</translation>
    </message>
    <message>
        <source>Nose radius: tip path by TolTurn</source>
        <translation>Eckenradius: Spitzenbahn von TolTurn</translation>
    </message>
    <message>
        <source>G42: the program is the contour and the control offsets it by the nose radius in its tool data. Tip path: TolTurn offsets it, for controls without compensation.</source>
        <translation>G42: das Programm ist die Kontur, und die Steuerung versetzt sie um den Eckenradius aus ihren Werkzeugdaten. Spitzenbahn: TolTurn versetzt sie, für Steuerungen ohne Korrektur.</translation>
    </message>
    <message>
        <source>Not optimised yet. Press F5 (or Optimise) to find the cutting conditions that hold every tolerance at least time or cost; the cutting window, the clamping ranking and the compensation follow. Planning Data… holds the rates, tool life and the insert&apos;s ranges the optimiser works with.</source>
        <translation>Noch nicht optimiert. Drücken Sie F5 (oder Optimieren), um die Schnittwerte zu finden, die jede Toleranz bei minimaler Zeit oder minimalen Kosten einhalten; Schnittwertfenster, Rangfolge der Aufspannungen und Kompensation folgen. Planungsdaten… enthält die Kostensätze, die Standzeit und die Bereiche der Wendeschneidplatte, mit denen die Optimierung rechnet.</translation>
    </message>
    <message>
        <source>programmed</source>
        <translation>programmiert</translation>
    </message>
    <message>
        <source>programmed (f %1 mm/rev, %2 %3) lies outside this window</source>
        <translation>programmiert (f %1 mm/U, %2 %3) liegt außerhalb dieses Fensters</translation>
    </message>
    <message>
        <source>vc</source>
        <translation>vc</translation>
    </message>
    <message>
        <source>ap</source>
        <translation>ap</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>n [rpm]</source>
        <translation>n [1/min]</translation>
    </message>
    <message>
        <source>vc [m/min]</source>
        <translation>vc [m/min]</translation>
    </message>
    <message>
        <source>f [mm/rev]</source>
        <translation>f [mm/U]</translation>
    </message>
    <message>
        <source>ap [mm]</source>
        <translation>ap [mm]</translation>
    </message>
    <message>
        <source>Power [kW]</source>
        <translation>Leistung [kW]</translation>
    </message>
    <message>
        <source>Time [min]</source>
        <translation>Zeit [min]</translation>
    </message>
    <message>
        <source>The optimal passes as the program would cut them: the spindle speed range under G96 and the spindle limit, the cutting power Fc·vc and the time along the tool path</source>
        <translation>Die optimalen Schnitte, wie das Programm sie ausführen würde: der Drehzahlbereich unter G96 und der Drehzahlbegrenzung, die Schnittleistung Fc·vc und die Zeit entlang der Werkzeugbahn</translation>
    </message>
    <message>
        <source>%1 (no currency set in Preferences)</source>
        <translation>%1 (keine Währung in den Einstellungen)</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>The project has problems (listed under Problems): nothing is planned or programmed until they are repaired.</source>
        <translation>Das Projekt hat Probleme (aufgeführt unter Probleme): Bis sie behoben sind, wird nichts geplant oder programmiert.</translation>
    </message>
    <message>
        <source>Make These Operations</source>
        <translation>Diese Aufspannungen anlegen</translation>
    </message>
    <message>
        <source>Add the proposed set-up to the project (undoable); Edit &gt; Operations… changes it</source>
        <translation>Die vorgeschlagene Aufspannung dem Projekt hinzufügen (rückgängig zu machen); Bearbeiten &gt; Aufspannungen… ändert sie</translation>
    </message>
    <message>
        <source>Split into operations: %1.</source>
        <translation>In Aufspannungen aufteilen: %1.</translation>
    </message>
    <message>
        <source>Feed schedule</source>
        <translation>Vorschubplan</translation>
    </message>
    <message>
        <source>Adaptive</source>
        <translation>Adaptiv</translation>
    </message>
    <message>
        <source>Cut each feature of the finishing pass at its feed of the Adaptive tab&apos;s schedule (compensated too: the features no feed holds keep the programmed feed and are compensated at it)</source>
        <translation>Jedes Formelement des Schlichtschnitts mit seinem Vorschub aus dem Plan der Registerkarte Adaptiv drehen (auch kompensiert: die Formelemente, die kein Vorschub hält, behalten den programmierten Vorschub und werden bei ihm kompensiert)</translation>
    </message>
    <message>
        <source>The optimisation failed: %1</source>
        <translation>Die Optimierung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Violated: %1 %2</source>
        <translation>Verletzt: %1 %2</translation>
    </message>
    <message>
        <source>To meet it: </source>
        <translation>Um sie einzuhalten: </translation>
    </message>
    <message numerus="yes">
        <source>Roughing: %n pass(es) at vc %1 m/min, f %2 mm/rev</source>
        <translation>
            <numerusform>Schruppen: %n Schnitt bei vc %1 m/min, f %2 mm/rev</numerusform>
            <numerusform>Schruppen: %n Schnitte bei vc %1 m/min, f %2 mm/rev</numerusform>
        </translation>
    </message>
    <message>
        <source>tool edges %1 per part</source>
        <translation>Schneiden %1 je Teil</translation>
    </message>
    <message>
        <source>tool edges not known (no tool life)</source>
        <translation>Schneiden nicht bekannt (keine Standzeit)</translation>
    </message>
    <message>
        <source>Time per part %1 min (finishing %2 min, roughing %3 min, handling %4 min, tool changes %5); cost %6; %7</source>
        <translation>Zeit je Teil %1 min (Schlichten %2 min, Schruppen %3 min, Handhabung %4 min, Werkzeugwechsel %5); Kosten %6; %7</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>nicht bekannt</translation>
    </message>
    <message>
        <source>The project&apos;s passes: %1. Dialect: %2. Program %3, checksum %4.</source>
        <translation>Die Schnitte des Projekts: %1. Dialekt: %2. Programm %3, Prüfsumme %4.</translation>
    </message>
</context>
<context>
    <name>tolturn::ProblemNavigator</name>
    <message>
        <source>No problems: every value of the project can be computed with.</source>
        <translation>Keine Probleme: Mit jedem Wert des Projekts kann gerechnet werden.</translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) stop the computation. Double-click one to go to its value; the results return once all are repaired.</source>
        <translation>
            <numerusform>%n Problem verhindert die Berechnung. Doppelklicken Sie darauf, um zu seinem Wert zu gelangen; die Ergebnisse erscheinen wieder, sobald es behoben ist.</numerusform>
            <numerusform>%n Probleme verhindern die Berechnung. Doppelklicken Sie auf eines, um zu seinem Wert zu gelangen; die Ergebnisse erscheinen wieder, sobald alle behoben sind.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProfileView</name>
    <message>
        <source>Drag to move this corner (snaps to %1 %3; Shift: %2 %3)</source>
        <translation>Ziehen, um diese Ecke zu verschieben (Raster %1 %3; Umschalt: %2 %3)</translation>
    </message>
    <message>
        <source>z %1 %3, Ø %2 %3</source>
        <translation>z %1 %3, Ø %2 %3</translation>
    </message>
    <message>
        <source>No part is open.

Open an example part: File &gt; Open Example
Import a turned part from STEP or IGES: File &gt; Import STEP/IGES… (Ctrl+I)
Draw a new part: File &gt; New (Ctrl+N), then edit its features
Open a project: File &gt; Open… (Ctrl+O)</source>
        <translation>Kein Teil geöffnet.

Ein Beispielteil öffnen: Datei &gt; Beispiel öffnen
Ein Drehteil aus STEP oder IGES einlesen: Datei &gt; STEP/IGES importieren… (Strg+I)
Ein neues Teil zeichnen: Datei &gt; Neu (Strg+N), dann seine Formelemente bearbeiten
Ein Projekt öffnen: Datei &gt; Öffnen… (Strg+O)</translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectAnalysis</name>
    <message numerus="yes">
        <source>Not computed: the project has %n problem(s), listed under Problems. Double-click one to go to its value.</source>
        <translation>
            <numerusform>Nicht berechnet: Das Projekt hat %n Problem, aufgeführt unter Probleme. Doppelklicken Sie darauf, um zu seinem Wert zu gelangen.</numerusform>
            <numerusform>Nicht berechnet: Das Projekt hat %n Probleme, aufgeführt unter Probleme. Doppelklicken Sie auf eines, um zu seinem Wert zu gelangen.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Add tolerance %1</source>
        <translation>Toleranz %1 hinzufügen</translation>
    </message>
    <message>
        <source>there is no tolerance %1</source>
        <translation>es gibt keine Toleranz %1</translation>
    </message>
    <message>
        <source>Edit tolerance %1</source>
        <translation>Toleranz %1 bearbeiten</translation>
    </message>
    <message>
        <source>Remove tolerance %1</source>
        <translation>Toleranz %1 entfernen</translation>
    </message>
    <message>
        <source>Set datum %1 on %2</source>
        <translation>Bezug %1 auf %2 setzen</translation>
    </message>
    <message>
        <source>Change planning settings</source>
        <translation>Planungseinstellungen ändern</translation>
    </message>
    <message>
        <source>Change material to %1</source>
        <translation>Werkstoff in %1 ändern</translation>
    </message>
    <message>
        <source>Change machine to %1</source>
        <translation>Maschine in %1 ändern</translation>
    </message>
    <message>
        <source>Change tool</source>
        <translation>Werkzeug ändern</translation>
    </message>
    <message>
        <source>Change clamping</source>
        <translation>Aufspannung ändern</translation>
    </message>
    <message>
        <source>Change machine stiffness</source>
        <translation>Maschinensteifigkeit ändern</translation>
    </message>
    <message>
        <source>Change force model</source>
        <translation>Kraftmodell ändern</translation>
    </message>
    <message>
        <source>Change shop conditions</source>
        <translation>Werkstattbedingungen ändern</translation>
    </message>
    <message>
        <source>Change boring bar</source>
        <translation>Bohrstange ändern</translation>
    </message>
    <message>
        <source>Change operations</source>
        <translation>Aufspannungen ändern</translation>
    </message>
    <message>
        <source>the project has no operation %1 any more</source>
        <translation>das Projekt hat keine Aufspannung %1 mehr</translation>
    </message>
</context>
<context>
    <name>tolturn::SettingsDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>Millimetres (lengths in mm, deviations in µm)</source>
        <translation>Millimeter (Längen in mm, Abweichungen in µm)</translation>
    </message>
    <message>
        <source>Inches (lengths in in, deviations in µin)</source>
        <translation>Zoll (Längen in in, Abweichungen in µin)</translation>
    </message>
    <message>
        <source>Lengths on the drawing, in the feature and set-up panels and in the plots; deviations in the plots and the verdict table. Files, reports, cutting data and the ISO 286 tables stay in millimetres and micrometres.</source>
        <translation>Längen in der Zeichnung, in den Bereichen Formelement und Einrichtung und in den Diagrammen; Abweichungen in den Diagrammen und der Bewertungstabelle. Dateien, Berichte, Schnittdaten und die Tabellen nach ISO 286 bleiben in Millimetern und Mikrometern.</translation>
    </message>
    <message>
        <source>A new language is used when TolTurn is next started.</source>
        <translation>Eine neue Sprache wird beim nächsten Start von TolTurn verwendet.</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>&amp;Units:</source>
        <translation>&amp;Einheiten:</translation>
    </message>
    <message>
        <source>name in the report&apos;s title block</source>
        <translation>Name im Schriftfeld des Berichts</translation>
    </message>
    <message>
        <source>&amp;Planner:</source>
        <translation>&amp;Planer:</translation>
    </message>
    <message>
        <source>e.g. EUR, of the machine rate and tool costs</source>
        <translation>z. B. EUR, der Maschinen- und Werkzeugkosten</translation>
    </message>
    <message>
        <source>&amp;Currency:</source>
        <translation>&amp;Währung:</translation>
    </message>
    <message>
        <source>Measurement store</source>
        <translation>Messwertspeicher</translation>
    </message>
    <message>
        <source>On this &amp;computer: %1</source>
        <translation>Auf diesem &amp;Computer: %1</translation>
    </message>
    <message>
        <source>&amp;Shop database (PostgreSQL), shared by every planner</source>
        <translation>&amp;Werkstattdatenbank (PostgreSQL), von allen Planern gemeinsam genutzt</translation>
    </message>
    <message>
        <source>server name, or the folder of its socket (/var/run/postgresql)</source>
        <translation>Servername oder der Ordner seines Sockets (/var/run/postgresql)</translation>
    </message>
    <message>
        <source>&amp;Test Connection</source>
        <translation>Verbindung &amp;testen</translation>
    </message>
    <message>
        <source>TolTurn keeps no password: libpq reads it from ~/.pgpass, or the server needs none (peer authentication).</source>
        <translation>TolTurn speichert kein Passwort: libpq liest es aus ~/.pgpass, oder der Server braucht keines (Peer-Authentifizierung).</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <source>&amp;Database:</source>
        <translation>&amp;Datenbank:</translation>
    </message>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Benutzer:</translation>
    </message>
    <message>
        <source>host</source>
        <translation>Host</translation>
    </message>
    <message>
        <source>database</source>
        <translation>Datenbank</translation>
    </message>
    <message>
        <source>user</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>The shop database needs its %1.</source>
        <translation>Für die Werkstattdatenbank fehlt: %1.</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbindung zu %1 wird hergestellt…</translation>
    </message>
    <message>
        <source>Connected to %1.</source>
        <translation>Mit %1 verbunden.</translation>
    </message>
</context>
<context>
    <name>tolturn::SetupPanel</name>
    <message>
        <source>Kienzle: Fc = kc1.1 · b · h^(1 − mc) (MODEL.md §2, Kienzle 1952).</source>
        <translation>Kienzle: Fc = kc1.1 · b · h^(1 − mc) (MODEL.md §2, Kienzle 1952).</translation>
    </message>
    <message>
        <source>%1 (not in the data library)</source>
        <translation>%1 (nicht in der Datenbibliothek)</translation>
    </message>
    <message>
        <source>Length of the part in the jaws from its left end; the chuck face is at this z. The part is a beam built in there (Valiño et al. 2008, eq. 2–5).</source>
        <translation>Länge des Teils in den Spannbacken ab seinem linken Ende; die Futterstirnfläche liegt bei diesem z. Dort ist das Teil als eingespannter Balken modelliert (Valiño et al. 2008, Gl. 2–5).</translation>
    </message>
    <message>
        <source>Tool length out of the turret for the toolpost term (Valiño et al. 2008, eq. 6); &apos;from holder&apos; uses the holder&apos;s length.</source>
        <translation>Werkzeuglänge außerhalb des Revolvers für den Werkzeugträgeranteil (Valiño et al. 2008, Gl. 6); „aus Halter“ verwendet die Länge des Halters.</translation>
    </message>
    <message>
        <source>from holder</source>
        <translation>aus Halter</translation>
    </message>
    <message>
        <source>Material and machine</source>
        <translation>Werkstoff und Maschine</translation>
    </message>
    <message>
        <source>&amp;Material:</source>
        <translation>&amp;Werkstoff:</translation>
    </message>
    <message>
        <source>Mac&amp;hine:</source>
        <translation>&amp;Maschine:</translation>
    </message>
    <message>
        <source>Stiffness:</source>
        <translation>Steifigkeit:</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>ISO 1832 designation, e.g. CNMG 120408: shape, clearance, tolerance, type, size, thickness, corner radius.</source>
        <translation>Bezeichnung nach ISO 1832, z. B. CNMG 120408: Form, Freiwinkel, Toleranz, Typ, Größe, Dicke, Eckenradius.</translation>
    </message>
    <message>
        <source>&amp;Insert (ISO 1832):</source>
        <translation>Wendeschneid&amp;platte (ISO 1832):</translation>
    </message>
    <message>
        <source>H&amp;older (ISO 5608):</source>
        <translation>&amp;Halter (ISO 5608):</translation>
    </message>
    <message>
        <source>&amp;Overhang:</source>
        <translation>&amp;Auskraglänge:</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Aufspannung</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Spannart:</translation>
    </message>
    <message>
        <source>Clamped &amp;length:</source>
        <translation>&amp;Einspannlänge:</translation>
    </message>
    <message>
        <source>Cutting conditions</source>
        <translation>Schnittbedingungen</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>vc [m/min]</source>
        <translation>vc [m/min]</translation>
    </message>
    <message>
        <source>f [mm/rev]</source>
        <translation>f [mm/rev]</translation>
    </message>
    <message>
        <source>ap [mm]</source>
        <translation>ap [mm]</translation>
    </message>
    <message>
        <source>Cutting speed vc: spindle speed n = 1000 vc / (π D).</source>
        <translation>Schnittgeschwindigkeit vc: Drehzahl n = 1000 vc / (π D).</translation>
    </message>
    <message>
        <source>Feed f: chip thickness h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).</source>
        <translation>Vorschub f: Spanungsdicke h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).</translation>
    </message>
    <message>
        <source>Depth of cut ap: chip width b = ap / sin κr (Kienzle).</source>
        <translation>Schnitttiefe ap: Spanungsbreite b = ap / sin κr (Kienzle).</translation>
    </message>
    <message>
        <source>corner %1°, nose radius %2 mm</source>
        <translation>Eckenwinkel %1°, Eckenradius %2 mm</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>spindle k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad</source>
        <translation>Spindel k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad</translation>
    </message>
    <message>
        <source>tailstock %1 N/mm</source>
        <translation>Reitstock %1 N/mm</translation>
    </message>
    <message>
        <source>centres %1 N/mm</source>
        <translation>Spitzen %1 N/mm</translation>
    </message>
    <message>
        <source>measured (%1): %2</source>
        <translation>gemessen (%1): %2</translation>
    </message>
    <message>
        <source>Change cutting conditions</source>
        <translation>Schnittbedingungen ändern</translation>
    </message>
    <message>
        <source>Machine stiffness not applied yet: %1.</source>
        <translation>Maschinensteifigkeit noch nicht übernommen: %1.</translation>
    </message>
    <message>
        <source>Measured Test Bar</source>
        <translation>Gemessener Prüfstab</translation>
    </message>
    <message>
        <source>Measurements (*.csv *.txt);;All files (*)</source>
        <translation>Messungen (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Enter Lc, the distance of the front spindle bearing behind the chuck face, before fitting the springs.</source>
        <translation>Geben Sie vor der Anpassung der Federn Lc ein, den Abstand des vorderen Spindellagers hinter der Futterfläche.</translation>
    </message>
    <message>
        <source>No springs fitted: %1</source>
        <translation>Keine Federn angepasst: %1</translation>
    </message>
    <message>
        <source>Test bar fit (Valiño et al. 2008 §III) of %1, %2: %3 points, RMS residual %4 µm, forces of the project&apos;s model</source>
        <translation>Prüfstab-Anpassung (Valiño et al. 2008 §III) von %1, %2: %3 Punkte, RMS-Restfehler %4 µm, Kräfte aus dem Modell des Projekts</translation>
    </message>
    <message>
        <source>Springs fitted to %1 points (RMS %2 µm)%3; the bar&apos;s own bending was %4 % of the deviation at its far end.</source>
        <translation>Federn an %1 Punkte angepasst (RMS %2 µm)%3; die Biegung des Stabs selbst war %4 % der Abweichung an seinem freien Ende.</translation>
    </message>
    <message>
        <source>, radial and tangential</source>
        <translation>, radial und tangential</translation>
    </message>
    <message>
        <source>, radial only</source>
        <translation>, nur radial</translation>
    </message>
    <message>
        <source>not measured: the chuck is the published range of chuck stiffness, results at both ends; tailstock and centres are rigid for want of data (see the banner above the verdicts). Measure k1, k2, k3 (Valiño et al. 2008 §III) below or fit them to a test bar.</source>
        <translation>nicht gemessen: das Futter ist der veröffentlichte Bereich der Futtersteifigkeit, Ergebnisse an beiden Enden; Reitstock und Spitzen sind mangels Daten starr (siehe das Banner über den Bewertungen). Messen Sie k1, k2, k3 (Valiño et al. 2008 §III) unten oder passen Sie sie an einen Prüfstab an.</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <source>The number of the part drawing the tolerances come from (report title block)</source>
        <translation>Die Nummer der Teilezeichnung, aus der die Toleranzen stammen (Schriftfeld des Berichts)</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Drawing no.:</source>
        <translation>&amp;Zeichnungsnr.:</translation>
    </message>
    <message>
        <source>&amp;Revision:</source>
        <translation>&amp;Revision:</translation>
    </message>
    <message>
        <source>Diameter of the bar the part is turned from: the roughing passes remove the stock between it and the profile.</source>
        <translation>Durchmesser der Stange, aus der das Teil gedreht wird: Die Schruppschnitte tragen das Material zwischen ihr und der Kontur ab.</translation>
    </message>
    <message>
        <source>&amp;Stock Ø:</source>
        <translation>&amp;Rohteil-Ø:</translation>
    </message>
    <message>
        <source>Change part name, drawing or stock</source>
        <translation>Teilename, Zeichnung oder Rohteil ändern</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>Schruppen</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>Schlichten</translation>
    </message>
    <message>
        <source>Boring bar</source>
        <translation>Bohrstange</translation>
    </message>
    <message>
        <source>The bar that cuts the inner contour. Without one the bores are computed as if cut by the turning tool, without the bending of a bar.</source>
        <translation>Die Stange, die die Innenkontur bearbeitet. Ohne sie werden die Bohrungen berechnet, als würden sie mit dem Drehwerkzeug bearbeitet, ohne die Biegung einer Stange.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 (Ø%2 mm, %3)</source>
        <translation>%1 (Ø%2 mm, %3)</translation>
    </message>
    <message>
        <source>material unknown</source>
        <translation>Werkstoff unbekannt</translation>
    </message>
    <message>
        <source>ISO 1832 designation of the boring bar&apos;s insert: its nose radius and the bar&apos;s entering angle give the forces in the bores.</source>
        <translation>ISO-1832-Bezeichnung der Wendeschneidplatte der Bohrstange: ihr Eckenradius und der Einstellwinkel der Stange ergeben die Kräfte in den Bohrungen.</translation>
    </message>
    <message>
        <source>bore depth</source>
        <translation>Bohrungstiefe</translation>
    </message>
    <message>
        <source>The cutting edge&apos;s distance from the bar&apos;s axis, the maker&apos;s dimension f: the arm of the torque that twists the bar. &apos;bar radius&apos; takes the least it can be.</source>
        <translation>Abstand der Schneide von der Stangenachse, das Maß f des Herstellers: der Hebelarm des Moments, das die Stange verdreht. &apos;Stangenradius&apos; nimmt das Kleinstmögliche.</translation>
    </message>
    <message>
        <source>bar radius</source>
        <translation>Stangenradius</translation>
    </message>
    <message>
        <source>&amp;Bar:</source>
        <translation>&amp;Stange:</translation>
    </message>
    <message>
        <source>Insert (ISO 1832):</source>
        <translation>Wendeschneidplatte (ISO 1832):</translation>
    </message>
    <message>
        <source>Bar o&amp;verhang:</source>
        <translation>&amp;Auskraglänge:</translation>
    </message>
    <message>
        <source>Edge offset f:</source>
        <translation>Schneidenversatz f:</translation>
    </message>
    <message>
        <source>The part has bores: without a boring bar they are computed as if cut by the turning tool, without the bending of a bar.</source>
        <translation>Das Teil hat Bohrungen: ohne Bohrstange werden sie berechnet, als würden sie mit dem Drehwerkzeug bearbeitet, ohne die Biegung einer Stange.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar of the data library.</source>
        <translation>&quot;%1&quot; ist keine Bohrstange der Datenbibliothek.</translation>
    </message>
    <message>
        <source>L/D %1</source>
        <translation>L/D %1</translation>
    </message>
    <message>
        <source>L/D from the reach of the bore</source>
        <translation>L/D aus der Reichweite der Bohrung</translation>
    </message>
    <message>
        <source>%1 bar, E = %2 GPa; %3; the maker allows up to %4 × D (%5).</source>
        <translation>Stange aus %1, E = %2 GPa; %3; der Hersteller lässt bis zu %4 × D zu (%5).</translation>
    </message>
    <message>
        <source>left end (as drawn)</source>
        <translation>linkes Ende (wie gezeichnet)</translation>
    </message>
    <message>
        <source>right end (turned end for end)</source>
        <translation>rechtes Ende (Teil umgedreht)</translation>
    </message>
    <message>
        <source>The end of the drawing the chuck holds (between centres: the driven end). Held at its right end, the part is computed and programmed turned end for end.</source>
        <translation>Das Ende der Zeichnung, das im Spannfutter gespannt ist (zwischen Spitzen: das angetriebene Ende). Am rechten Ende gespannt, wird das Teil umgedreht berechnet und programmiert.</translation>
    </message>
    <message>
        <source>Held &amp;end:</source>
        <translation>&amp;Gespanntes Ende:</translation>
    </message>
    <message>
        <source>Boundary conditions of the workpiece beam: built in at the chuck face, supported by the tailstock centre, or by two centres (MODEL.md §3); a collet is built in at its face, its stiffness not published (taken as rigid, said in the verdicts).</source>
        <translation>Randbedingungen des Werkstückbalkens: an der Futterstirnseite eingespannt, von der Reitstockspitze gestützt oder zwischen zwei Spitzen (MODEL.md §3); eine Spannzange spannt an ihrer Stirnseite ein, ihre Steifigkeit ist nicht veröffentlicht (als starr angenommen, in den Bewertungen genannt).</translation>
    </message>
    <message>
        <source>Diameter of the hole drilled (or cored) before the bar starts: the program roughs the bore from it. &apos;not given&apos; takes the bore as roughed to its finishing allowance before the program.</source>
        <translation>Durchmesser der Bohrung, die vor der Stange gebohrt (oder vorgegossen) wird: Das Programm schruppt die Bohrung von ihr aus. „nicht angegeben“ nimmt die Bohrung als vor dem Programm auf ihr Schlichtaufmaß vorgeschruppt an.</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>Pilot &amp;hole Ø:</source>
        <translation>&amp;Vorbohrung Ø:</translation>
    </message>
    <message>
        <source>Length of the bar out of its clamping to the cutting edge. &apos;bore depth&apos; takes the least that reaches the deepest bore from the right end face, with the turret 2 mm off it.</source>
        <translation>Länge der Stange von ihrer Einspannung bis zur Schneide. &apos;Bohrungstiefe&apos; nimmt das Mindeste, das die tiefste Bohrung von der rechten Stirnfläche aus erreicht, mit dem Revolver 2 mm davor.</translation>
    </message>
</context>
<context>
    <name>tolturn::SolidCheckDialog</name>
    <message>
        <source>The largest edge of the tetrahedra gmsh meshes the part with: smaller is more exact and slower</source>
        <translation>Die größte Kantenlänge der Tetraeder, mit denen gmsh das Teil vernetzt: kleiner ist genauer und langsamer</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Check with Solid FE</source>
        <translation>Mit FE-Volumenmodell prüfen</translation>
    </message>
    <message>
        <source>%1: %2, %3 end held</source>
        <translation>%1: %2, Ende %3 gespannt</translation>
    </message>
    <message>
        <source>The part of the set-up is meshed in quadratic tetrahedra with gmsh, held as its clamping holds it, loaded by the cutting force at each station and solved with CalculiX; its deflection is compared with the beam&apos;s. A coarse mesh takes seconds, a fine one minutes. The project is not changed.</source>
        <translation>Das Teil der Aufspannung wird mit gmsh in quadratische Tetraeder vernetzt, so gehalten, wie seine Aufspannung es hält, an jeder Station mit der Schnittkraft belastet und mit CalculiX gelöst; seine Verformung wird mit der des Balkens verglichen. Ein grobes Netz braucht Sekunden, ein feines Minuten. Das Projekt wird nicht geändert.</translation>
    </message>
    <message>
        <source>The set-up checked: its part as held and its finishing pass&apos;s force</source>
        <translation>Die geprüfte Aufspannung: ihr Teil wie gespannt und die Kraft ihres Schlichtschnitts</translation>
    </message>
    <message>
        <source>Tool positions, evenly along the supported length: one load case of CalculiX each</source>
        <translation>Werkzeugstellungen, gleichmäßig über die abgestützte Länge verteilt: je ein Lastfall für CalculiX</translation>
    </message>
    <message>
        <source>Operation:</source>
        <translation>Aufspannung:</translation>
    </message>
    <message>
        <source>Stations:</source>
        <translation>Stationen:</translation>
    </message>
    <message>
        <source>Mesh size:</source>
        <translation>Netzgröße:</translation>
    </message>
    <message>
        <source>default %1 %2: a fifth of the smallest outer diameter between the supports</source>
        <translation>Standard %1 %2: ein Fünftel des kleinsten Außendurchmessers zwischen den Abstützungen</translation>
    </message>
    <message>
        <source>Choose a mesh size of at least %1 %2: a finer mesh of a whole part takes gmsh and CalculiX hours and more memory than the computer has.</source>
        <translation>Wählen Sie eine Netzgröße von mindestens %1 %2: Ein feineres Netz eines ganzen Teils kostet gmsh und CalculiX Stunden und mehr Speicher, als der Rechner hat.</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Prüfung läuft…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <source>done — %p%</source>
        <translation>fertig — %p%</translation>
    </message>
    <message>
        <source>The project cannot be checked:</source>
        <translation>Das Projekt kann nicht geprüft werden:</translation>
    </message>
    <message>
        <source>The check needs gmsh and CalculiX, and one of them is missing:</source>
        <translation>Die Prüfung braucht gmsh und CalculiX, und eines davon fehlt:</translation>
    </message>
    <message>
        <source>Meshing the part failed:</source>
        <translation>Das Vernetzen des Teils ist fehlgeschlagen:</translation>
    </message>
    <message>
        <source>Solving failed:</source>
        <translation>Das Lösen ist fehlgeschlagen:</translation>
    </message>
    <message>
        <source>The check was cancelled; the project is unchanged.</source>
        <translation>Die Prüfung wurde abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>Checked in %1 s. The beam&apos;s radial deflection differs from the solid&apos;s by at most %2 % of the largest deflection.</source>
        <translation>Geprüft in %1 s. Die radiale Verformung des Balkens weicht von der des Volumenmodells um höchstens %2 % der größten Durchbiegung ab.</translation>
    </message>
</context>
<context>
    <name>tolturn::SolidCheckView</name>
    <message>
        <source>z [%1]</source>
        <translation>z [%1]</translation>
    </message>
    <message>
        <source>Ø [%1]</source>
        <translation>Ø [%1]</translation>
    </message>
    <message>
        <source>beam radial [%1]</source>
        <translation>Balken radial [%1]</translation>
    </message>
    <message>
        <source>solid radial [%1]</source>
        <translation>Volumen radial [%1]</translation>
    </message>
    <message>
        <source>beam − solid [%]</source>
        <translation>Balken − Volumen [%]</translation>
    </message>
    <message>
        <source>beam tangential [%1]</source>
        <translation>Balken tangential [%1]</translation>
    </message>
    <message>
        <source>solid tangential [%1]</source>
        <translation>Volumen tangential [%1]</translation>
    </message>
    <message>
        <source>The tool position, from the end the set-up holds</source>
        <translation>Die Werkzeugstellung, vom Ende aus, das die Aufspannung hält</translation>
    </message>
    <message>
        <source>(beam − solid) / solid of the radial deflection: positive where the beam is the softer</source>
        <translation>(Balken − Volumen) / Volumen der radialen Verformung: positiv, wo der Balken der weichere ist</translation>
    </message>
    <message>
        <source>Radial deflection of the part under the cutting force</source>
        <translation>Radiale Verformung des Teils unter der Schnittkraft</translation>
    </message>
    <message>
        <source>z from the held end [%1]</source>
        <translation>z vom gespannten Ende [%1]</translation>
    </message>
    <message>
        <source>radial deflection [%1]</source>
        <translation>radiale Verformung [%1]</translation>
    </message>
    <message>
        <source>beam</source>
        <translation>Balken</translation>
    </message>
    <message>
        <source>solid (CalculiX)</source>
        <translation>Volumenmodell (CalculiX)</translation>
    </message>
    <message>
        <source>Mesh: C3D10 tetrahedra of at most %1 %2, %3 nodes, %4 elements, %5 degrees of freedom · gmsh %6 s, CalculiX %7 s</source>
        <translation>Netz: C3D10-Tetraeder von höchstens %1 %2, %3 Knoten, %4 Elemente, %5 Freiheitsgrade · gmsh %6 s, CalculiX %7 s</translation>
    </message>
    <message>
        <source>Held: %1 · E = %2 MPa, ν = %3 · force at each station: Fc %4 N, Ff %5 N, Fp %6 N</source>
        <translation>Gespannt: %1 · E = %2 MPa, ν = %3 · Kraft an jeder Station: Fc %4 N, Ff %5 N, Fp %6 N</translation>
    </message>
    <message>
        <source>Timoshenko radial [%1]</source>
        <translation>Timoshenko radial [%1]</translation>
    </message>
    <message>
        <source>The beam without its corrections for the root in the jaws and the shoulders (docs/solid-fe.md)</source>
        <translation>Der Balken ohne seine Korrekturen für die Einspannung in den Backen und die Absätze (docs/solid-fe.md)</translation>
    </message>
    <message>
        <source>beam without corrections</source>
        <translation>Balken ohne Korrekturen</translation>
    </message>
    <message>
        <source>beam (corrected)</source>
        <translation>Balken (korrigiert)</translation>
    </message>
</context>
<context>
    <name>tolturn::StiffnessEditor</name>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Measured machine stiffness</source>
        <translation>Gemessene Maschinensteifigkeit</translation>
    </message>
    <message>
        <source>Spindle–chuck springs (Valiño et al. 2008, §III, eq. 2–4): k1 radial translation [N/mm], k2 and k3 rotation [N·mm/rad] about the pivot Lc behind the chuck face.</source>
        <translation>Federn Spindel–Futter (Valiño et al. 2008, §III, Gl. 2–4): k1 radiale Verschiebung [N/mm], k2 und k3 Verdrehung [N·mm/rad] um den Drehpunkt Lc hinter der Futterstirnfläche.</translation>
    </message>
    <message>
        <source>Support stiffness of the centre at the part&apos;s right (or both) ends [N/mm], as a spring under the workpiece beam (MODEL.md §3).</source>
        <translation>Stützsteifigkeit der Spitze am rechten Ende (oder an beiden Enden) des Teils [N/mm], als Feder unter dem Werkstückbalken (MODEL.md §3).</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Lc: distance of the k2 spring behind the chuck face (Valiño et al. 2008, Fig. 2).</source>
        <translation>Lc: Abstand der k2-Feder hinter der Futterstirnfläche (Valiño et al. 2008, Abb. 2).</translation>
    </message>
    <message>
        <source>who measured it, when, how</source>
        <translation>wer hat gemessen, wann, wie</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>Quelle:</translation>
    </message>
    <message>
        <source>Lc:</source>
        <translation>Lc:</translation>
    </message>
    <message>
        <source>k1 [N/mm]</source>
        <translation>k1 [N/mm]</translation>
    </message>
    <message>
        <source>k2 [N·mm/rad]</source>
        <translation>k2 [N·mm/rad]</translation>
    </message>
    <message>
        <source>k3 [N·mm/rad]</source>
        <translation>k3 [N·mm/rad]</translation>
    </message>
    <message>
        <source>radial [N/mm]</source>
        <translation>radial [N/mm]</translation>
    </message>
    <message>
        <source>tangential [N/mm]</source>
        <translation>tangential [N/mm]</translation>
    </message>
    <message>
        <source>Spindle radial</source>
        <translation>Spindel radial</translation>
    </message>
    <message>
        <source>Spindle tangential</source>
        <translation>Spindel tangential</translation>
    </message>
    <message>
        <source>Tailstock</source>
        <translation>Reitstock</translation>
    </message>
    <message>
        <source>Centres</source>
        <translation>Spitzen</translation>
    </message>
    <message>
        <source> Radial.</source>
        <translation> Radial.</translation>
    </message>
    <message>
        <source> Tangential.</source>
        <translation> Tangential.</translation>
    </message>
    <message>
        <source>spindle radial k1, k2, k3</source>
        <translation>Spindel radial k1, k2, k3</translation>
    </message>
    <message>
        <source>spindle tangential k1, k2, k3</source>
        <translation>Spindel tangential k1, k2, k3</translation>
    </message>
    <message>
        <source>tailstock radial and tangential</source>
        <translation>Reitstock radial und tangential</translation>
    </message>
    <message>
        <source>centres radial and tangential</source>
        <translation>Spitzen radial und tangential</translation>
    </message>
    <message>
        <source>enter all of %1</source>
        <translation>geben Sie alle Werte an: %1</translation>
    </message>
    <message>
        <source>enter the pivot distance Lc of the spindle springs</source>
        <translation>geben Sie den Drehpunktabstand Lc der Spindelfedern an</translation>
    </message>
    <message>
        <source>enter where the numbers come from (source)</source>
        <translation>geben Sie an, woher die Werte stammen (Quelle)</translation>
    </message>
    <message>
        <source>Fit from Test Bar…</source>
        <translation>Aus Prüfstab anpassen…</translation>
    </message>
    <message>
        <source>Valiño et al. 2008 §III: the open project is a stiff bar turned in the chuck; a CSV of its measured deviation (z_mm, radial_um, optionally tangential_um) gives k1, k2, k3 for the Lc entered above.</source>
        <translation>Valiño et al. 2008 §III: das offene Projekt ist ein steifer, im Futter gedrehter Stab; eine CSV-Datei seiner gemessenen Abweichung (z_mm, radial_um, wahlweise tangential_um) ergibt k1, k2, k3 für das oben eingegebene Lc.</translation>
    </message>
</context>
<context>
    <name>tolturn::ToleranceDialog</name>
    <message>
        <source>ISO 286 class</source>
        <translation>Toleranzklasse ISO 286</translation>
    </message>
    <message>
        <source>Limit deviations</source>
        <translation>Grenzabmaße</translation>
    </message>
    <message>
        <source>Add Tolerance</source>
        <translation>Toleranz hinzufügen</translation>
    </message>
    <message>
        <source>Edit Tolerance %1</source>
        <translation>Toleranz %1 bearbeiten</translation>
    </message>
    <message>
        <source>To face</source>
        <translation>Bis Planfläche</translation>
    </message>
    <message>
        <source>Upper deviation</source>
        <translation>Oberes Grenzabmaß</translation>
    </message>
    <message>
        <source>Lower deviation</source>
        <translation>Unteres Grenzabmaß</translation>
    </message>
    <message>
        <source>e.g. h6, H7, js12</source>
        <translation>z. B. h6, H7, js12</translation>
    </message>
    <message>
        <source>ISO 286-1 tolerance class: small letters for shafts, capitals for holes.</source>
        <translation>Toleranzklasse nach ISO 286-1: Kleinbuchstaben für Wellen, Großbuchstaben für Bohrungen.</translation>
    </message>
    <message>
        <source>Tolerance zone t</source>
        <translation>Toleranzzone t</translation>
    </message>
    <message>
        <source>Datums</source>
        <translation>Bezüge</translation>
    </message>
    <message>
        <source>no datum defined yet</source>
        <translation>noch kein Bezug definiert</translation>
    </message>
    <message>
        <source>e.g. A; defined: %1</source>
        <translation>z. B. A; definiert: %1</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Eigenschaft</translation>
    </message>
    <message>
        <source>at %1 mm: upper %2 µm, lower %3 µm (%4 = %5 µm)</source>
        <translation>bei %1 mm: oberes Grenzabmaß %2 µm, unteres %3 µm (%4 = %5 µm)</translation>
    </message>
</context>
<context>
    <name>tolturn::TolerancePanel</name>
    <message>
        <source>Add…</source>
        <translation>Hinzufügen…</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Bearbeiten…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Set Datum…</source>
        <translation>Bezug setzen…</translation>
    </message>
    <message>
        <source>Add a tolerance on the feature selected in the drawing</source>
        <translation>Eine Toleranz an dem in der Zeichnung ausgewählten Formelement hinzufügen</translation>
    </message>
    <message>
        <source>Make the feature selected in the drawing a datum (ISO 5459)</source>
        <translation>Das in der Zeichnung ausgewählte Formelement zu einem Bezug machen (ISO 5459)</translation>
    </message>
    <message>
        <source>Set Datum</source>
        <translation>Bezug setzen</translation>
    </message>
    <message>
        <source>Datum letter for feature %1 (ISO 5459):</source>
        <translation>Bezugsbuchstabe für Formelement %1 (ISO 5459):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Machine:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Maschine:&lt;/b&gt; %1</translation>
    </message>
</context>
<context>
    <name>tolturn::ToleranceVerdictModel</name>
    <message>
        <source>%1/%2 µm</source>
        <translation>%1/%2 µm</translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Eigenschaft</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Formelement</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Spezifikation</translation>
    </message>
    <message>
        <source>Utilisation</source>
        <translation>Ausnutzung</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>Predicted [%1]</source>
        <translation>Vorhergesagt [%1]</translation>
    </message>
    <message>
        <source>Limit [%1]</source>
        <translation>Grenze [%1]</translation>
    </message>
    <message>
        <source>chuck %1</source>
        <translation>Futter %1</translation>
    </message>
    <message>
        <source>tailstock %1</source>
        <translation>Reitstock %1</translation>
    </message>
    <message>
        <source>The smallest radial stiffness of the chuck (at its face) and of the tailstock (or of both centres) with which this tolerance passes as programmed at the planned conditions, the other supports as assumed.</source>
        <translation>Die kleinste radiale Steifigkeit des Futters (an seiner Stirn) und des Reitstocks (oder beider Spitzen), mit der diese Toleranz bei den geplanten Bedingungen wie programmiert erfüllt wird, die übrigen Lager wie angenommen.</translation>
    </message>
    <message>
        <source>On the machine range</source>
        <translation>Über den Maschinenbereich</translation>
    </message>
    <message>
        <source>Stiffness needed</source>
        <translation>Nötige Steifigkeit</translation>
    </message>
    <message>
        <source>%1 is cut in %2: choose that set-up to see its verdict</source>
        <translation>%1 wird in %2 bearbeitet: wählen Sie diese Aufspannung, um ihre Bewertung zu sehen</translation>
    </message>
    <message>
        <source>collet %1</source>
        <translation>Spannzange %1</translation>
    </message>
</context>
</TS>

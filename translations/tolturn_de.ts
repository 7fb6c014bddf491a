<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>ClampingAdvice</name>
    <message>
        <source>meets every constraint: %1 %2 per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 by %2 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no plan meets every constraint: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no cylinder at the left end of the part for the chuck jaws to grip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot be planned</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]

TolTurn&apos;s command-line front end: the same computations as the desktop program, headless, for batch use and regression tests.

Commands:
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Run &apos;%1 COMMAND --help&apos; for the options of a command.
Exit codes: 0 success, 1 the input has errors, 2 wrong command line.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Usage: %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give exactly one project file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part &quot;%1&quot;, %2 mm long, %3 outer and %4 inner features, %5, %6 passes, %7 tolerances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the findings as JSON on standard output.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project files to check.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no project file given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ok</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max %8 kW, %9 N·m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>note: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feature  side   z from–to [mm]    radial deviation [µm] min … max   diameter error [µm] min … max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1 at z = %2 mm: tan(theta) = %3, axial run-out e = %4 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use these forces [N] instead of the force model: radial, tangential, axial.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rigid machine supports, no toolpost or thermal term: the beam alone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool positions per turned feature (default 21).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index of the pass (default: the last finishing pass).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore the stock still on the uncut side of the tool.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--stations must be a whole number from 2 to 100000, not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--pass must be a pass index (0, 1, …), not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--load takes three numbers in newtons, radial,tangential,axial (e.g. 200,500,150), not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>K_n = %1 N/mm², K_f = %2 (Li &amp; Du eq. 15), RMS residual %3 N over %4 cuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>   f [mm/rev]  d [mm]   Ft meas   Ft model   Fa meas   Fa model   Fr model [N]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store K_n and K_f in the project (force model li_du) and save it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file (its tool gives the geometry).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV of measured cuts: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a project file and a measurements file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wrote %1: force model li_du</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the nominal size must be a number in mm, not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the limits as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nominal size [mm].</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance class, e.g. H7, g6, js12.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a nominal size and a tolerance class, e.g. 50 H7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2: upper %3 µm, lower %4 µm (%5 = %6 µm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the fit as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hole and shaft class, e.g. H7/g6.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give a nominal size and a fit, e.g. 50 H7/g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2/%3: %4 fit; hole %5/%6 µm, shaft %7/%8 µm; clearance max %9 µm, min %10 µm (negative: interference)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the verdicts as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance  type                    feature  value [µm]  limit [µm]  use [%]  verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optimum (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No plan meets every constraint; the one that violates them least</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  time per part %1 min (finishing %2, roughing %3), cost %4, %5 tool edges per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  roughing: %1 passes of ap %2 mm at vc %3 m/min, f %4 mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  binding: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  violated: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the plan as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time or cost (default: the project&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store the optimal passes in the project (replacing its passes) and save it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--objective is time or cost, not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wrote %1: %2 passes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed-speed (default) or feed-depth.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print every grid point as CSV.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points along each axis (default 256).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give one project file, --plane feed-speed or feed-depth, --size from 2 to 4096</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 × %2 window, %3 % feasible; optimum at f = %4 mm/rev, %5 = %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  bounded by %1 (%2 points beyond it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the ranking as JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correct the path where a tolerance needs it (offset or profile).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give one project file and -o FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2, residual %3 -&gt; %4 µm %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF file to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give one project file and -o FILE.pdf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 pages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validate project files: report every problem with the field and value; exit 1 on errors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Predict the deviation at each tool position along every turned feature: radial and tangential, total and per contribution (spindle–chuck, toolpost, workpiece, thermal), with the forces used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the Li &amp; Du coefficients K_n and K_f to measured tangential and axial forces (eq. 17–18) for the project&apos;s tool; --write stores them in the project.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISO 286 limits of a tolerance class at a nominal size, e.g. &apos;iso286 50 H7&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISO 286 fit of a hole and a shaft class, e.g. &apos;fit 50 H7/g6&apos;: type and clearances.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every tolerance of the project against the predicted deviation: value, limit, utilisation, the deciding condition of Valiño et al. Fig. 4, and the verdict.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting conditions of the finishing and roughing passes at least time or cost per part under every constraint (tolerances, roughness, power, torque, force, spindle speed, tool life).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cutting window of the finishing pass around the optimum: per grid point the objective, whether it is feasible and the constraint that bounds it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The optimal plan for chuck, between centres and chuck + tailstock, ranked, with the reason.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The finishing path of the outer contour as ISO 6983 G-code, nominal or compensated only where a tolerance needs it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PDF report: part, inputs, predicted deviation, tolerance verdicts, plan with the cutting window, clamping ranking, compensation, assumptions and sources.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown command &apos;%2&apos;. Run &apos;%1 --help&apos; for the list of commands.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Compensation</name>
    <message>
        <source>the face&apos;s conicity needs a correction along Z, which TolTurn does not generate: reduce the feed or change the clamping</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CuttingModels</name>
    <message>
        <source>%1 = %2 is outside the range %3 &lt; %1 &lt; %4 in which %5 is stated to hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chip thickness h = f sin(kappa_r) = %1 mm is outside the range %2–%3 mm over which the Kienzle constants of this material were measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lead angle [°]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nose radius [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002) needs a nose radius larger than the feed, but r_n = %1 mm and f = %2 mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no force measurements given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the measurements do not determine K_n and K_f (rank %1 of 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fitted normal pressure K_n = %1 N/mm² is not positive: check the measured forces and the tool angles</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DataFiles</name>
    <message>
        <source>cannot open the data file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a valid JSON object: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected format &quot;%1&quot; version 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>required value is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected {&quot;value&quot;: number, &quot;source&quot;: key of &quot;sources&quot;}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>material &quot;%1&quot; lacks its id, modulus, density or Kienzle constants</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DeviationModel</name>
    <message>
        <source>Feed and passive force from the rule of thumb Ff = %1 Fc, Fp = %2 Fc (%3): the material data give no feed or passive force constants. Calibrate the forces for accuracy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no source: zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toolpost shortening not included: holder &quot;%1&quot; is not in the data library.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toolpost: the whole holder length (%1 mm) is taken in compression, an upper bound; give tool.overhang_mm for the length out of the turret.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Workpiece only: machine supports rigid, no toolpost or thermal term.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle–chuck not characterised for this machine: the part is taken as rigidly clamped at the chuck face. Measure k1, k2, k3 (Valiño et al. 2008 §III) for its contribution.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Headstock centre not characterised: taken as a rigid pin.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tailstock not characterised: taken as a rigid pin.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown material &quot;%1&quot;; the data library has: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>material &quot;%1&quot; has no Poisson&apos;s ratio in the data, which the shear deflection needs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library and its ISO 5608 style letter (third character) gives no known entering angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Li &amp; Du model needs the rake and inclination angles of the tool; the data give none for holder &quot;%1&quot; with insert &quot;%2&quot;: set tool.rake_deg and tool.inclination_deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the force model needs a known material and holder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no cutting pass; the deviation is that of the pass that finishes the features</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no pass %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown machine &quot;%1&quot;; the data library has: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 clamping with these supports leaves the part free to move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Thermal drift not characterised for this machine: taken as zero.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the pass needs %1 kW of cutting power, more than the machine&apos;s %2 kW</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>InsertCodes</name>
    <message>
        <source>insert code &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an ISO 1832 designation (four letters, then size, thickness and corner digits, as in CNMG 120408)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 1 (shape) &apos;%1&apos; is not one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 2 (clearance angle) &apos;%1&apos; is not one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 3 (tolerance class) &apos;%1&apos; is not one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 4 (type) &apos;%1&apos; is not one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 5 (size) &apos;%1&apos; is not a standard cutting-edge length for shape %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 6 (thickness) &apos;%1&apos; is not an ISO 1832 thickness symbol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 7 of a round insert is M0 or 00, not &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 7 (corner radius) &apos;%1&apos; gives a sharp corner, which turning inserts of shape %2 do not have in TolTurn&apos;s models</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Iso286</name>
    <message>
        <source>hole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>shaft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the nominal size is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 mm is not a nominal size: the first range of ISO 286 is above 0 up to and including 3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the nominal size must be above 0 mm, but is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm is above 3150 mm, the largest nominal size of ISO 286</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is given by ISO 286-1 only for nominal sizes up to and including 500 mm, not for %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 shall not be used for nominal sizes up to and including 1 mm (ISO 286-1 Table 1), but the size is %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 above 500 mm is given by ISO 286-1 for experimental use only (size %2 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole %1 is not defined: ISO 286-1 forms %2 up to IT%3 as ES = -ei + Δ, and tabulates Δ only for IT3 to IT8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 gives K above IT8 only for nominal sizes up to and including 3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 says N above IT8 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 says the fundamental deviations %4 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives the fundamental deviation %4 only above %5 mm up to and including %6 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is not defined: ISO 286-1 tabulates %3 only for the grades IT%4 to IT%5 (the symmetric %6 covers every grade)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives %4 only up to and including 500 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives j8 only up to and including 3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the tolerance class is empty; write a fundamental deviation letter and a tolerance grade, such as H7 or g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tolerance class: write a fundamental deviation letter and a tolerance grade, such as H7, g6 or js6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; mixes upper and lower case in &quot;%2&quot;: hole letters are upper case (H7), shaft letters lower case (g6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not a fundamental deviation of ISO 286-1; the %3 letters are %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: IT%2 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IT%1 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a shaft class; the first class of a fit is the hole, written in upper case (H7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a hole class; the second class of a fit is the shaft, written in lower case (g6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>clearance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>transition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the designation is empty; write one such as 50 H7, Ø50 g6 or 50 H7/g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the diameter sign must be followed by the nominal size, as in Ø50 H7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no tolerance class; write one after the nominal size, such as 50 H7 or 50 H7/g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a designation: a fit is a hole class, a slash and a shaft class, as in 50 H7/g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: a fit is written hole class first (upper case), then the shaft class (lower case), as in 50 H7/g6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the designation &quot;%1&quot; names %2 mm, but %3 mm was given separately</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no nominal size; write it in the designation (50 H7) or give it separately</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>JsonReading</name>
    <message>
        <source>null</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>true</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the number %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the text &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this field is required but missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown %1 &quot;%2&quot;; expected one of: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown field, ignored</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MeasurementFiles</name>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the header lacks the column &quot;%1&quot;; it needs %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 must be a number%2, not &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> above zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file has no header line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file has no measurement</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Names</name>
    <message>
        <source>chuck</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>between centres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chuck + tailstock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flatness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cylindricity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>profile of a surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parallelism</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>perpendicularity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coaxiality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>circular radial run-out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>circular axial run-out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total radial run-out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total axial run-out</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Planning</name>
    <message>
        <source>tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the optimiser needs the insert&apos;s ranges of cutting speed, feed and depth of cut (from its maker&apos;s catalogue), with their source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No Taylor constants in the project&apos;s planning data: tool life and tool cost are not in the objective, and there is no tool-life constraint.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No spindle torque limit given (planning.max_torque_Nm): torque is not constrained.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PlotExport</name>
    <message>
        <source>cannot export a plot as &apos;%1&apos;: use .png, .svg or .pdf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy Data as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Image…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProfileEditing</name>
    <message>
        <source>the %1 contour has no vertex %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a step is inserted into a cylinder; %1 is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the step of %1 must lie inside it (z %2 … %3 mm), but z is %4 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the step&apos;s diameter must differ from Ø%1 mm and be above zero, but is %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1 of the %2 contour is not a corner between two features</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a corner is broken between a face and a cylinder; %1 and %2 are not</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the corner of %1 and %2 takes at most %3 mm, but the size is %4 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edge round</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cone is made from a cylinder; %1 is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the cone&apos;s end needs a diameter other than Ø%1 mm, but it is %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cylinder is made from a cone; %1 is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a bore starts at an end face of the part; %1 is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the part is bored already; edit its bore instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a bore needs a depth and a diameter above zero, but they are %1 and %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bore bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no feature %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is an end of the %2 contour; move it instead of deleting it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the features beside %1 are parallel: there is no corner to give back</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProfileValidation</name>
    <message>
        <source>the coordinate is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must not be negative, but is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 runs backwards along z, from z = %2 mm to z = %3 mm: a contour runs from left to right, so this segment overlaps the one before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cylinder keeps one radius, but this one goes from r = %1 mm to r = %2 mm (a cone?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the cylinder has zero length: it starts and ends at z = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a cylinder needs a radius above zero, but r = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a face stays at one z, but this one goes from z = %1 mm to z = %2 mm (a cone?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the face has zero length: it starts and ends at r = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 must advance along z, but it starts and ends at z = %2 mm (a face?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 must change radius, but it stays at r = %2 mm (a cylinder?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the radius must be above zero, but is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the radius has zero length: both ends are at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a radius of %1 mm cannot join two points %2 mm apart (it needs at least %3 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 arc of radius %2 mm turns back along z (an undercut), which cannot be turned from left to right; try the other direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overlaps %1: it starts at %2, left of where %1 ends, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>leaves a gap: it starts at %2, but %1 ends at %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the face turns back over %1 at z = %2 mm: the two faces overlap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the outer contour must start at the left end of the part, z = 0 mm, but starts at z = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the part has zero length: the outer contour ends at z = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the left end face must start at r = %1 mm (%2), but starts at r = %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the bore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the right end face must end at r = %1 mm (%2), but ends at r = %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the inner contour must start at the left end (z = 0 mm) or on the axis (r = 0 mm), but starts at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the inner contour must end at the right end (z = %1 mm) or on the axis (r = 0 mm), but ends at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the bore is closed at both ends (a cavity that no tool can reach): it must open at z = 0 mm or at z = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the bore ends at z = %1 mm, beyond the right end of the part at z = %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the bore reaches r = %1 mm at z = %2 mm, where the outer contour is at r = %3 mm: the inner radius meets the outer one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every feature needs an id, but this one is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used by another feature; ids must be unique</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the stock diameter must be above zero, but is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the outer contour has no segments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the stock diameter %1 mm is smaller than the part, whose largest diameter is %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProjectFile</name>
    <message>
        <source>&apos;%1&apos; does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a folder, not a project file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2 MiB, more than the %3 MiB a project file may have</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProjectJson</name>
    <message>
        <source>segment type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>arc direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a segment object, found %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>objective</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>clamping method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object, found %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pass kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a datum letter, found %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this is not a TolTurn project: format is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown format version %1; this TolTurn reads version %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid JSON at line %1, column %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a project file holds one JSON object, not a list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProjectValidation</name>
    <message>
        <source>%1 is missing (empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be zero or more, but is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a part held in a chuck needs a clamped length above zero, but it is %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clamped length %1 mm leaves nothing to turn on a part %2 mm long</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a part between centres is not clamped; the clamped length %1 mm is ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be above zero, but is %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a datum is named by one or two capital letters (ISO 5459), not &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is defined twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give either an ISO 286 class or both limit deviations (upper_um, lower_um)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an ISO 286 tolerance class (a letter and a grade, e.g. h6 or H7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a shaft class, but feature &apos;%2&apos; is a bore: use capital letters (e.g. H7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a hole class, but feature &apos;%2&apos; is an outer surface: use small letters (e.g. h6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>both limit deviations are needed, upper_um and lower_um</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the upper deviation %1 µm must be above the lower deviation %2 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 tolerance needs a zone width above zero, but it is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 tolerance is defined relative to a datum, but none is given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is not defined in the project&apos;s datums</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a %1 tolerance cannot sit on feature &apos;%2&apos;, which is a %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a length runs between two faces; there is no feature &apos;%1&apos; in the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a length runs between two different faces; &apos;%1&apos; is not one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every tolerance needs an id, but this one is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be zero or more, but is %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the li_du force model needs normal_pressure_MPa (K_n) and friction_ratio (K_f); fit them from measured forces with &apos;tolturn-cli calibrate-forces&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>where the machine characterisation comes from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle springs need the pivot distance Lc of the k2 spring behind the chuck face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be at least the minimum %1, but is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Taylor exponent n lies between 0 and 1, but is %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the source of the Taylor constants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the source of the cutting ranges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown constraint &quot;%1&quot;; the constraints are: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the work material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the insert code</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Datum %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>Tolerance report: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project %1 · %2 · TolTurn %3 · length %4 mm, stock Ø%5 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1  Part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2  Inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2° corner, nose radius %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: entering angle %2°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, clamped length %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: vc %2 m/min, f %3 mm/rev, ap %4 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine characterisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not characterised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3  Predicted deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finishing pass %1: forces (%2) Fc %3 N, Ff %4 N, Fp %5 N; theoretical Ra %6 µm, Rz %7 µm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial deviation of the outer contour (material left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial deviation of the bores (material left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tan θ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axial run-out e [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>4  Tolerances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project has no tolerances.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Specification</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>optimum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass (green: feasible)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>5  Plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project has no planning data (the insert&apos;s cutting ranges), so no plan was optimised.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optimal plan (%1): </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one (%1): </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 min per part; finishing vc %2 m/min, f %3 mm/rev, ap %4 mm; %5 roughing passes at vc %6 m/min, f %7 mm/rev.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 violated by %2 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Binding: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rank</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensation of the project&apos;s finishing pass, only where a tolerance needs it:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>6  Assumptions and sources</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model: G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos, Machining error predictive model in a CAPP system for turning (2008): eq. 2–8 (deviation), §V and Fig. 4 (tolerances), §VI (optimisation). X. Li, R. Du, Analysis and compensation of workpiece errors in turning, Int. J. Prod. Res. 40(7) (2002): eq. 15–20 (forces), §3.4 (compensation). Kienzle (1952) forces; Timoshenko beam with the shear coefficient of G. R. Cowper (1966); ISO 286-1/-2 limits; ISO 1101 characteristics. The equations as implemented, their corrections and the validation: docs/model.md in TolTurn.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material data (%1): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elastic constants: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting ranges: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TolTurn report: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ToleranceVerdicts</name>
    <message>
        <source>feature %1 is not cut in this set-up (it lies in the chuck jaws or outside the supported length), so no deviation is predicted for it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the limits of %1 at %2 mm cannot be formed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 13: D&apos;_Md &lt;= Dn + dDu and D&apos;_md &gt;= Dn + dDl</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4b: eq. 13 fails as programmed, eq. 15 holds: 2|delta_TMd - delta_Tmd| &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a constant tool offset of %1 µm on the diameter centres the size in its tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| &gt; t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4a, eq. 11–12: e_i + e_j &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4e, eq. 22: delta_TMd + delta_Tmd &lt;= t / cos(alpha)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4e: eq. 22 fails as programmed; the spread of the normal deviation fits in t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a constant offset of %1 µm normal to the surface centres it in the zone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4e, eq. 22: the spread of the normal deviation exceeds t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4c, eq. 16: e_i &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4f, eq. 23: e_j &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4i, §V.J (eq. 16 and 24): e_j &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4g, eq. 24 (face to the datum axis): e_j &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Perpendicularity of an axis to a face depends on how the part is aligned in the lathe; the axis recovers elastically after cutting, so the cutting-force deflection does not decide it (Valiño et al. 2008 §V.G.2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4d, eq. 19: |delta_TMd - delta_Tmd| &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fig. 4h, §V.J (eq. 19): |delta_TMd - delta_Tmd| &lt;= t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coaxiality limits how far parts of the axis lie apart; the axis recovers elastically after cutting, so the error comes from set-up and alignment, not from the cutting-force deflection (Valiño et al. 2008 §V.H).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The deflection under the cutting force is symmetrical about the axis of rotation and leaves no circular run-out; that comes from clamping deformation or misalignment (Valiño et al. 2008 §V.I).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>passes as programmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>passes after a constant offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs a profile correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not predicted by this model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot be evaluated</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tolerance-aware planning of CNC turning.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file to open (.tolturn).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::AboutDialog</name>
    <message>
        <source>&lt;p&gt;Tolerance-aware planning of CNC turning: deflection of machine, workpiece and tool, ISO 286 and ISO 1101 verdicts, and cutting conditions that hold them.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later). There is no warranty.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Licence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About TolTurn</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::DeflectionPanel</name>
    <message>
        <source>Outer contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inner contour (bores)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial deviation by contribution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tangential deviation by contribution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial deviation: material left on the surface, δ_T = δ_sc + δ_tp + δ_p + δ_th (Valiño et al. 2008, eq. 2). Diameter error: 2 (r - r_nominal) with the radial and tangential deviation combined exactly.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle–chuck / supports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>workpiece</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>toolpost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>thermal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial deviation (material left on the surface)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tangential deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter error: machined minus nominal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter error [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces (%1): Fc %2 N, Ff %3 N, Fp %4 N · pass %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::FeaturePanel</name>
    <message>
        <source>z of the start, from the part&apos;s left end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter at the start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z of the end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter at the end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the step is, inside the cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter after the step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert &amp;Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chamfer leg (45°) or radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make C&amp;one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth of the bore from this end face; the part&apos;s length bores through</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter of the bore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Bore from This Face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start z:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start Ø:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End z:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End Ø:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step (cylinders)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At z:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To Ø:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Break a corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chamfer start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chamfer end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Round start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Round end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bore (solid part, end face)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ø:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click a feature of the drawing to edit it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; %2 — %3, %4 contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make C&amp;ylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move corner of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move corner to z %1, Ø %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert step into %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Round corner of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chamfer corner of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make %1 a cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make %1 a cone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bore from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::FileController</name>
    <message>
        <source>TolTurn projects (*.tolturn *.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New project: a plain bar to shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file was not opened; the current project is unchanged.

%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the unsaved project &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot recover %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The copy %1 cannot be read; it is kept.

%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot export the report</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Report written to %1 (%n page(s))</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot save %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project was not saved; the file on disk is unchanged.

%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::MainWindow</name>
    <message>
        <source>Open a project (File &gt; Open) or an example part (File &gt; Open Example).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Planning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Example</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;Report…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About TolTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1[*] — TolTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — length %2 mm, Ø max %3 mm, %4 outer / %5 inner features, clamping: %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TolTurn did not close normally. A copy of %1 with unsaved changes was kept at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recover it? A discarded copy is deleted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningPanel</name>
    <message>
        <source>Optimise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply to Passes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export G-code…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Least time per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Least cost per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Window: feed – cutting speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Window: feed – depth of cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Constraints:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the %1 constraint on or off (docs/planning.md §2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rank</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting Window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.tap);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply optimal passes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optimal plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time per part %1 min (finishing %2 min, roughing %3 min); cost %4; tool edges %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Roughing: %1 passes at vc %2 m/min, f %3 mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Binding: %1 (%2 of %3 %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Violated: %1 by %2 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Note: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Green&lt;/b&gt;: feasible, darker is better.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>optimum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – cutting speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – depth of cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth of cut ap [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constant offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>profile correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::ProfileView</name>
    <message>
        <source>Drag to move this corner (snaps to %1 mm; Shift: 0.01 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z %1 mm, Ø %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectDocument</name>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set datum %1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change planning settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change material to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change machine to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change clamping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change machine stiffness</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::SetupPanel</name>
    <message>
        <source>Kienzle: Fc = kc1.1 · b · h^(1 − mc) (MODEL.md §2, Kienzle 1952).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (not in the data library)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length of the part in the jaws from its left end; the chuck face is at this z. The part is a beam built in there (Valiño et al. 2008, eq. 2–5).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool length out of the turret for the toolpost term (Valiño et al. 2008, eq. 6); &apos;from holder&apos; uses the holder&apos;s length.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>from holder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material and machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Material:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mac&amp;hine:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stiffness:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISO 1832 designation, e.g. CNMG 120408: shape, clearance, tolerance, type, size, thickness, corner radius.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Insert (ISO 1832):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>H&amp;older (ISO 5608):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Overhang:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boundary conditions of the workpiece beam: built in at the chuck face, supported by the tailstock centre, or by two centres (MODEL.md §3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clamped &amp;length:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting conditions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vc [m/min]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>f [mm/rev]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ap [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting speed vc: spindle speed n = 1000 vc / (π D).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed f: chip thickness h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth of cut ap: chip width b = ap / sin κr (Kienzle).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner %1°, nose radius %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not characterised: the supports are taken as rigid. Measure k1, k2, k3 (Valiño et al. 2008 §III) and enter them in the project.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tailstock %1 N/mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centres %1 N/mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured (%1): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change cutting conditions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine stiffness not applied yet: %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::StiffnessEditor</name>
    <message>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured machine stiffness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle–chuck springs (Valiño et al. 2008, §III, eq. 2–4): k1 radial translation [N/mm], k2 and k3 rotation [N·mm/rad] about the pivot Lc behind the chuck face.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Support stiffness of the centre at the part&apos;s right (or both) ends [N/mm], as a spring under the workpiece beam (MODEL.md §3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lc: distance of the k2 spring behind the chuck face (Valiño et al. 2008, Fig. 2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>who measured it, when, how</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lc:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k1 [N/mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k2 [N·mm/rad]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k3 [N·mm/rad]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radial [N/mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tangential [N/mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle radial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle tangential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tailstock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Centres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Radial.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Tangential.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle radial k1, k2, k3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spindle tangential k1, k2, k3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tailstock radial and tangential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centres radial and tangential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter all of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter the pivot distance Lc of the spindle springs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter where the numbers come from (source)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::ToleranceDialog</name>
    <message>
        <source>ISO 286 class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit deviations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add Tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Tolerance %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. h6, H7, js12</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISO 286-1 tolerance class: small letters for shafts, capitals for holes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance zone t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Datums</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no datum defined yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. A; defined: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at %1 mm: upper %2 µm, lower %3 µm (%4 = %5 µm)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::TolerancePanel</name>
    <message>
        <source>Add…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Datum…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a tolerance on the feature selected in the drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make the feature selected in the drawing a datum (ISO 5459)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Datum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Datum letter for feature %1 (ISO 5459):</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tolturn::ToleranceVerdictModel</name>
    <message>
        <source>%1/%2 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Specification</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Predicted [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limit [µm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Utilisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>

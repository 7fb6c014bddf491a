<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
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
        <translation>No se conoce límite de avance (los datos de planificación no dan un rango de avance): solo el %1 % del override limita el avance.</translation>
    </message>
    <message>
        <source>The feed is held at or below %1 mm/rev, the top of the plan&apos;s feed range (%2).</source>
        <translation>El avance se mantiene en %1 mm/rev como máximo, el extremo superior del rango de avance de la planificación (%2).</translation>
    </message>
    <message>
        <source>no source given</source>
        <translation>sin fuente</translation>
    </message>
    <message>
        <source>Forces from the project&apos;s %1 model; feed drive 1/(%2 s² + %3 s + 1) (Čuš &amp; Župerl eq. 1), control period %4 ms, feed override %5–%6 %.</source>
        <translation>Fuerzas del modelo %1 del proyecto; accionamiento de avance 1/(%2 s² + %3 s + 1) (Čuš &amp; Župerl ec. 1), periodo de control %4 ms, override de avance %5–%6 %.</translation>
    </message>
    <message>
        <source>Machine noise: %1 % of the force (standard deviation), seed %2.</source>
        <translation>Ruido de máquina: %1 % de la fuerza (desviación típica), semilla %2.</translation>
    </message>
    <message>
        <source>Machine noise: none (the force is measured exactly).</source>
        <translation>Ruido de máquina: ninguno (la fuerza se mide exactamente).</translation>
    </message>
    <message numerus="yes">
        <source>pass %1 does not exist: the plan has %n pass(es)</source>
        <translation>
            <numerusform>la pasada %1 no existe: el plan tiene %n pasada</numerusform>
            <numerusform>la pasada %1 no existe: el plan tiene %n pasadas</numerusform>
        </translation>
    </message>
    <message>
        <source>the tool cannot reach the part: it is held over its whole length</source>
        <translation>la herramienta no alcanza la pieza: está sujeta en toda su longitud</translation>
    </message>
    <message>
        <source>Pass %1: the feed is held at or below %2 mm/rev for %3 (f² / (32 r_e), f² / (8 r_e)).</source>
        <translation>Pasada %1: el avance se mantiene en %2 mm/rev como máximo por %3 (f² / (32 r_e), f² / (8 r_e)).</translation>
    </message>
    <message>
        <source>pass %1: the adaptive run was stopped after %2 h of cutting short of the end of the pass: the set force asks for a feed the pass hardly advances at</source>
        <translation>pasada %1: la simulación adaptativa se detuvo tras %2 h de corte antes del final de la pasada: la fuerza de consigna exige un avance con el que la pasada apenas progresa</translation>
    </message>
    <message>
        <source>pass %1 cuts up to %2 mm deep where the plan gives %3 mm: the passes before it leave more. The set force is the planned depth&apos;s, so the loop lowers the feed there; plan the passes to the stock</source>
        <translation>la pasada %1 corta hasta %2 mm de profundidad donde el plan da %3 mm: las pasadas anteriores dejan más. La fuerza de consigna es la de la profundidad planificada, así que el lazo baja el avance allí; planifique las pasadas según la pieza en bruto</translation>
    </message>
</context>
<context>
    <name>AtomicFile</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>no se puede escribir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: the data did not reach the disk</source>
        <translation>no se puede escribir &apos;%1&apos;: los datos no llegaron al disco</translation>
    </message>
    <message>
        <source>cannot set the permissions of &apos;%1&apos;: %2</source>
        <translation>no se pueden fijar los permisos de &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>no se puede guardar &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: it is not a regular file (a folder, a device or a pipe)</source>
        <translation>no se puede escribir &apos;%1&apos;: no es un archivo normal (una carpeta, un dispositivo o una tubería)</translation>
    </message>
</context>
<context>
    <name>BallEndMilling</name>
    <message>
        <source>overhang: %1 mm is not from the ball&apos;s radius, %2 mm, to 1000 mm</source>
        <translation>voladizo: %1 mm no está entre el radio de la bola, %2 mm, y 1000 mm</translation>
    </message>
    <message>
        <source>equivalent diameter: %1 mm is not above 0 and at most the tool&apos;s %2 mm</source>
        <translation>diámetro equivalente: %1 mm no es mayor que 0 y como mucho el de la herramienta, %2 mm</translation>
    </message>
    <message>
        <source>Young&apos;s modulus: %1 N/mm² is not positive</source>
        <translation>módulo de Young: %1 N/mm² no es positivo</translation>
    </message>
    <message>
        <source>holder stiffness k: %1 N/mm is not positive</source>
        <translation>rigidez del portaherramientas k: %1 N/mm no es positiva</translation>
    </message>
    <message>
        <source>holder rotational stiffness k_θ: %1 N·mm/rad is not positive</source>
        <translation>rigidez rotacional del portaherramientas k_θ: %1 N·mm/rad no es positiva</translation>
    </message>
    <message>
        <source>tool diameter: %1 mm is not a positive diameter</source>
        <translation>diámetro de la herramienta: %1 mm no es un diámetro positivo</translation>
    </message>
    <message>
        <source>flutes: %1 is not 1 to 12</source>
        <translation>filos: %1 no está entre 1 y 12</translation>
    </message>
    <message>
        <source>helix angle: %1° is not 0 to 60°</source>
        <translation>ángulo de hélice: %1° no está entre 0 y 60°</translation>
    </message>
    <message>
        <source>feed per tooth: %1 mm is not positive</source>
        <translation>avance por diente: %1 mm no es positivo</translation>
    </message>
    <message>
        <source>lead, tilt: %1°, %2° are not within ±60°</source>
        <translation>avance angular (lead), inclinación (tilt): %1°, %2° no están dentro de ±60°</translation>
    </message>
    <message>
        <source>radial depth: %1 mm is not positive</source>
        <translation>profundidad radial: %1 mm no es positiva</translation>
    </message>
    <message>
        <source>axial slices: %1 is not 1 to 100000</source>
        <translation>rodajas axiales: %1 no está entre 1 y 100000</translation>
    </message>
    <message>
        <source>angles per revolution: %1 is not 1 to 100000</source>
        <translation>ángulos por vuelta: %1 no está entre 1 y 100000</translation>
    </message>
    <message>
        <source>axial depth: %1 mm is not within the ball, 0 to %2 mm at lead %3° and tilt %4° (001 models the ball only)</source>
        <translation>profundidad axial: %1 mm no está dentro de la bola, de 0 a %2 mm con lead %3° y tilt %4° (001 modela solo la bola)</translation>
    </message>
    <message>
        <source>the tip of the ball, where the cutting speed is zero, is in the cut (lead %1°, tilt %2°): the force model takes no account of the rubbing there</source>
        <translation>la punta de la bola, donde la velocidad de corte es cero, está en el corte (lead %1°, tilt %2°): el modelo de fuerzas no tiene en cuenta el rozamiento allí</translation>
    </message>
    <message>
        <source>the lead is negative (%1°): the feed has a part along the tool axis and the cut drills, where 001 §5 finds its force model below the measured forces</source>
        <translation>el ángulo lead es negativo (%1°): el avance tiene una parte a lo largo del eje de la herramienta y el corte taladra, donde 001 §5 encuentra su modelo de fuerzas por debajo de las fuerzas medidas</translation>
    </message>
    <message>
        <source>the lateral force peaks at %1 N, beyond the 1000 N for which 001 calibrated the holder springs it gives (001 §4): the deflection there is an extrapolation; give your holder&apos;s springs</source>
        <translation>la fuerza lateral llega a %1 N, más que los 1000 N para los que 001 calibró los muelles del portaherramientas que da (001 §4): la deformación allí es una extrapolación; indique los muelles de su portaherramientas</translation>
    </message>
</context>
<context>
    <name>CadImportJson</name>
    <message>
        <source>the import&apos;s result has no valid &quot;%1&quot;</source>
        <translation>el resultado de la importación no tiene un «%1» válido</translation>
    </message>
    <message>
        <source>%1: expected an array, found %2</source>
        <translation>%1: se esperaba una matriz y se ha encontrado %2</translation>
    </message>
    <message>
        <source>%1: expected an object, found %2</source>
        <translation>%1: se esperaba un objeto y se ha encontrado %2</translation>
    </message>
    <message>
        <source>the import&apos;s result has no valid &quot;milled_features&quot;: %1</source>
        <translation>el resultado de la importación no tiene un «milled_features» válido: %1</translation>
    </message>
</context>
<context>
    <name>CalculixText</name>
    <message>
        <source>CalculiX wrote displacements for %1 of the %2 load cases</source>
        <translation>CalculiX escribió desplazamientos para %1 de los %2 casos de carga</translation>
    </message>
</context>
<context>
    <name>ClampingAdvice</name>
    <message>
        <source>meets every constraint: %1 %2 per part</source>
        <translation>cumple todas las restricciones: %1 %2 por pieza</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>cost</source>
        <translation>coste</translation>
    </message>
    <message>
        <source>no plan meets every constraint: %1</source>
        <translation>ningún plan cumple todas las restricciones: %1</translation>
    </message>
    <message>
        <source>no cylinder at the left end of the part for the chuck jaws to grip</source>
        <translation>no hay ningún cilindro en el extremo izquierdo de la pieza que puedan sujetar las garras del plato</translation>
    </message>
    <message>
        <source>cannot be planned</source>
        <translation>no se puede planificar</translation>
    </message>
    <message>
        <source>; deciding: %1, %2 of %3 %4 (%5 % used)</source>
        <translation>; decisiva: %1, %2 de %3 %4 (%5 % utilizado)</translation>
    </message>
    <message>
        <source>no cylinder at the right end of the part for the chuck jaws to grip</source>
        <translation>no hay ningún cilindro en el extremo derecho de la pieza que puedan sujetar las garras del plato</translation>
    </message>
    <message>
        <source>; the right end face is held by a centre: it is faced and centred before the set-up, not in this time</source>
        <translation>; la cara frontal derecha la sujeta un punto: se refrenta y se hace el centro antes del amarre, no en este tiempo</translation>
    </message>
    <message>
        <source>; not held to: %1</source>
        <translation>; no se tiene en cuenta: %1</translation>
    </message>
    <message>
        <source>meets every constraint it can check, but not every tolerance is one: %1 %2 per part</source>
        <translation>cumple todas las restricciones que puede comprobar, pero no todas las tolerancias lo son: %1 %2 por pieza</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]

TolTurn&apos;s command-line front end: the same computations as the desktop program, headless, for batch use and regression tests.

Commands:
</source>
        <translation>Uso: %1 [--help] [--version] COMANDO [ARGUMENTOS]

Interfaz de línea de comandos de TolTurn: los mismos cálculos que el programa de escritorio, sin interfaz gráfica, para procesamiento por lotes y pruebas de regresión.

Comandos:
</translation>
    </message>
    <message>
        <source>
Run &apos;%1 COMMAND --help&apos; for the options of a command.
Exit codes: 0 success, 1 the input has errors, 2 wrong command line.
</source>
        <translation>
Ejecute &apos;%1 COMANDO --help&apos; para ver las opciones de un comando.
Códigos de salida: 0 éxito, 1 la entrada tiene errores, 2 línea de comandos incorrecta.
</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Mostrar esta ayuda.</translation>
    </message>
    <message>
        <source>Usage: %1 %2</source>
        <translation>Uso: %1 %2</translation>
    </message>
    <message>
        <source>give exactly one project file</source>
        <translation>indique exactamente un archivo de proyecto</translation>
    </message>
    <message>
        <source>Print the findings as JSON on standard output.</source>
        <translation>Escribir los problemas detectados en formato JSON en la salida estándar.</translation>
    </message>
    <message>
        <source>Project files to check.</source>
        <translation>Archivos de proyecto que se van a comprobar.</translation>
    </message>
    <message>
        <source>no project file given</source>
        <translation>no se ha indicado ningún archivo de proyecto</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>correcto</translation>
    </message>
    <message>
        <source>Forces (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial</source>
        <translation>Fuerzas (%1): Fc = %2 N tangencial, Ff = %3 N axial, Fp = %4 N radial</translation>
    </message>
    <message>
        <source>Pass %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max %8 kW, %9 N·m</source>
        <translation>Pasada %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; máx. %8 kW, %9 N·m</translation>
    </message>
    <message>
        <source>note: </source>
        <translation>nota: </translation>
    </message>
    <message>
        <source>feature  side   z from–to [mm]    radial deviation [µm] min … max   diameter error [µm] min … max</source>
        <translation>elemento lado   z desde–hasta [mm] desviación radial [µm] mín … máx   error de diámetro [µm] mín … máx</translation>
    </message>
    <message>
        <source>face %1 at z = %2 mm: tan(theta) = %3, axial run-out e = %4 µm</source>
        <translation>cara %1 en z = %2 mm: tan(theta) = %3, oscilación axial e = %4 µm</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Escribir el resultado en formato JSON.</translation>
    </message>
    <message>
        <source>Use these forces [N] instead of the force model: radial, tangential, axial.</source>
        <translation>Usar estas fuerzas [N] en lugar del modelo de fuerzas: radial, tangencial, axial.</translation>
    </message>
    <message>
        <source>Rigid machine supports, no toolpost or thermal term: the beam alone.</source>
        <translation>Apoyos de la máquina rígidos, sin término de torreta ni térmico: solo la viga.</translation>
    </message>
    <message>
        <source>Tool positions per turned feature (default 21).</source>
        <translation>Posiciones de la herramienta por elemento torneado (por defecto 21).</translation>
    </message>
    <message>
        <source>Ignore the stock still on the uncut side of the tool.</source>
        <translation>Ignorar el material que aún queda en el lado no cortado de la herramienta.</translation>
    </message>
    <message>
        <source>Project file.</source>
        <translation>Archivo de proyecto.</translation>
    </message>
    <message>
        <source>--stations must be a whole number from 2 to 100000, not &quot;%1&quot;</source>
        <translation>--stations debe ser un número entero de 2 a 100000, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>K_n = %1 N/mm², K_f = %2 (Li &amp; Du eq. 15), RMS residual %3 N over %4 cuts</source>
        <translation>K_n = %1 N/mm², K_f = %2 (Li &amp; Du ec. 15), residuo RMS %3 N en %4 cortes</translation>
    </message>
    <message>
        <source>   f [mm/rev]  d [mm]   Ft meas   Ft model   Fa meas   Fa model   Fr model [N]</source>
        <translation>   f [mm/rev]  d [mm]   Ft med.  Ft modelo   Fa med.  Fa modelo  Fr modelo [N]</translation>
    </message>
    <message>
        <source>Store K_n and K_f in the project (force model li_du) and save it.</source>
        <translation>Almacenar K_n y K_f en el proyecto (modelo de fuerzas li_du) y guardarlo.</translation>
    </message>
    <message>
        <source>Project file (its tool gives the geometry).</source>
        <translation>Archivo de proyecto (su herramienta define la geometría).</translation>
    </message>
    <message>
        <source>CSV of measured cuts: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N.</source>
        <translation>CSV de cortes medidos: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N.</translation>
    </message>
    <message>
        <source>give a project file and a measurements file</source>
        <translation>indique un archivo de proyecto y un archivo de mediciones</translation>
    </message>
    <message>
        <source>wrote %1: force model li_du</source>
        <translation>se ha escrito %1: modelo de fuerzas li_du</translation>
    </message>
    <message>
        <source>the nominal size must be a number in mm, not &quot;%1&quot;</source>
        <translation>la medida nominal debe ser un número en mm, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Print the limits as JSON.</source>
        <translation>Escribir los límites en formato JSON.</translation>
    </message>
    <message>
        <source>Nominal size [mm].</source>
        <translation>Medida nominal [mm].</translation>
    </message>
    <message>
        <source>Tolerance class, e.g. H7, g6, js12.</source>
        <translation>Clase de tolerancia, p. ej. H7, g6, js12.</translation>
    </message>
    <message>
        <source>give a nominal size and a tolerance class, e.g. 50 H7</source>
        <translation>indique una medida nominal y una clase de tolerancia, p. ej. 50 H7</translation>
    </message>
    <message>
        <source>%1 %2: upper %3 µm, lower %4 µm (%5 = %6 µm)</source>
        <translation>%1 %2: superior %3 µm, inferior %4 µm (%5 = %6 µm)</translation>
    </message>
    <message>
        <source>Print the fit as JSON.</source>
        <translation>Escribir el ajuste en formato JSON.</translation>
    </message>
    <message>
        <source>Hole and shaft class, e.g. H7/g6.</source>
        <translation>Clase del agujero y del eje, p. ej. H7/g6.</translation>
    </message>
    <message>
        <source>give a nominal size and a fit, e.g. 50 H7/g6</source>
        <translation>indique una medida nominal y un ajuste, p. ej. 50 H7/g6</translation>
    </message>
    <message>
        <source>%1 %2/%3: %4 fit; hole %5/%6 µm, shaft %7/%8 µm; clearance max %9 µm, min %10 µm (negative: interference)</source>
        <translation>%1 %2/%3: ajuste %4; agujero %5/%6 µm, eje %7/%8 µm; juego máx. %9 µm, mín. %10 µm (negativo: apriete)</translation>
    </message>
    <message>
        <source>Print the verdicts as JSON.</source>
        <translation>Escribir los veredictos en formato JSON.</translation>
    </message>
    <message>
        <source>tolerance  type                    feature  value [µm]  limit [µm]  use [%]  verdict</source>
        <translation>tolerancia tipo                    elemento valor [µm] límite [µm]  uso [%]  veredicto</translation>
    </message>
    <message>
        <source>Optimum (%1)</source>
        <translation>Óptimo (%1)</translation>
    </message>
    <message>
        <source>No plan meets every constraint; the one that violates them least</source>
        <translation>Ningún plan cumple todas las restricciones; el que menos las incumple</translation>
    </message>
    <message>
        <source>  finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>  acabado: vc %1 m/min, f %2 mm/rev, ap %3 mm</translation>
    </message>
    <message>
        <source>  binding: </source>
        <translation>  restricciones activas: </translation>
    </message>
    <message>
        <source>  violated: </source>
        <translation>  restricciones incumplidas: </translation>
    </message>
    <message>
        <source>Print the plan as JSON.</source>
        <translation>Escribir el plan en formato JSON.</translation>
    </message>
    <message>
        <source>time or cost (default: the project&apos;s).</source>
        <translation>time o cost (por defecto: el del proyecto).</translation>
    </message>
    <message>
        <source>Store the optimal passes in the project (replacing its passes) and save it.</source>
        <translation>Almacenar las pasadas óptimas en el proyecto (sustituyendo sus pasadas) y guardarlo.</translation>
    </message>
    <message>
        <source>--objective is time or cost, not &quot;%1&quot;</source>
        <translation>--objective es time o cost, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>feed-speed (default) or feed-depth.</source>
        <translation>feed-speed (por defecto) o feed-depth.</translation>
    </message>
    <message>
        <source>Print every grid point as CSV.</source>
        <translation>Escribir cada punto de la malla en formato CSV.</translation>
    </message>
    <message>
        <source>Points along each axis (default 256).</source>
        <translation>Puntos en cada eje (por defecto 256).</translation>
    </message>
    <message>
        <source>give one project file, --plane feed-speed or feed-depth, --size from 2 to 4096</source>
        <translation>indique un archivo de proyecto, --plane feed-speed o feed-depth, --size de 2 a 4096</translation>
    </message>
    <message>
        <source>  bounded by %1 (%2 points beyond it)</source>
        <translation>  limitada por %1 (%2 puntos fuera de ella)</translation>
    </message>
    <message>
        <source>Print the ranking as JSON.</source>
        <translation>Escribir la clasificación en formato JSON.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE.pdf</source>
        <translation>indique un archivo de proyecto y -o ARCHIVO.pdf</translation>
    </message>
    <message>
        <source>%1: %2 pages</source>
        <translation>%1: %2 páginas</translation>
    </message>
    <message>
        <source>Validate project files: report every problem with the field and value; exit 1 on errors.</source>
        <translation>Validar archivos de proyecto: informar de cada problema con el campo y el valor; código de salida 1 si hay errores.</translation>
    </message>
    <message>
        <source>Predict the deviation at each tool position along every turned feature: radial and tangential, total and per contribution (spindle–chuck, toolpost, workpiece, thermal), with the forces used.</source>
        <translation>Predecir la desviación en cada posición de la herramienta a lo largo de cada elemento torneado: radial y tangencial, total y por contribución (husillo–plato, torreta, pieza, térmica), con las fuerzas utilizadas.</translation>
    </message>
    <message>
        <source>Fit the Li &amp; Du coefficients K_n and K_f to measured tangential and axial forces (eq. 17–18) for the project&apos;s tool; --write stores them in the project.</source>
        <translation>Ajustar los coeficientes K_n y K_f de Li &amp; Du a las fuerzas tangenciales y axiales medidas (ec. 17–18) para la herramienta del proyecto; --write los almacena en el proyecto.</translation>
    </message>
    <message>
        <source>ISO 286 limits of a tolerance class at a nominal size, e.g. &apos;iso286 50 H7&apos;.</source>
        <translation>Límites ISO 286 de una clase de tolerancia para una medida nominal, p. ej. &apos;iso286 50 H7&apos;.</translation>
    </message>
    <message>
        <source>ISO 286 fit of a hole and a shaft class, e.g. &apos;fit 50 H7/g6&apos;: type and clearances.</source>
        <translation>Ajuste ISO 286 entre una clase de agujero y una de eje, p. ej. &apos;fit 50 H7/g6&apos;: tipo y juegos.</translation>
    </message>
    <message>
        <source>Every tolerance of the project against the predicted deviation: value, limit, utilisation, the deciding condition of Valiño et al. Fig. 4, and the verdict.</source>
        <translation>Cada tolerancia del proyecto frente a la desviación prevista: valor, límite, utilización, la condición determinante de Valiño et al. Fig. 4 y el veredicto.</translation>
    </message>
    <message>
        <source>Cutting conditions of the finishing and roughing passes at least time or cost per part under every constraint (tolerances, roughness, power, torque, force, spindle speed, tool life).</source>
        <translation>Condiciones de corte de las pasadas de acabado y desbaste con el mínimo tiempo o coste por pieza respetando todas las restricciones (tolerancias, rugosidad, potencia, par, fuerza, velocidad del husillo, vida de la herramienta).</translation>
    </message>
    <message>
        <source>The cutting window of the finishing pass around the optimum: per grid point the objective, whether it is feasible and the constraint that bounds it.</source>
        <translation>La ventana de corte de la pasada de acabado alrededor del óptimo: para cada punto de la malla, el objetivo, si es factible y la restricción que lo limita.</translation>
    </message>
    <message>
        <source>The optimal plan for chuck, between centres and chuck + tailstock, ranked, with the reason.</source>
        <translation>El plan óptimo para plato, entre puntos y plato + contrapunto, clasificados y con el motivo.</translation>
    </message>
    <message>
        <source>The PDF report: part, inputs, predicted deviation, tolerance verdicts, plan with the cutting window, clamping ranking, compensation, assumptions and sources.</source>
        <translation>El informe PDF: pieza, datos de entrada, desviación prevista, veredictos de las tolerancias, plan con la ventana de corte, clasificación de sujeciones, compensación, hipótesis y fuentes.</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Máquina: %1</translation>
    </message>
    <message>
        <source>at the compliant end: %1</source>
        <translation>en el extremo flexible: %1</translation>
    </message>
    <message>
        <source>chuck stiffness needed: %1</source>
        <translation>rigidez necesaria del plato: %1</translation>
    </message>
    <message>
        <source>tailstock stiffness needed: %1</source>
        <translation>rigidez necesaria del contrapunto: %1</translation>
    </message>
    <message>
        <source>Plan for the compliant (default) or the stiff end of an unmeasured machine&apos;s stiffness range.</source>
        <translation>Planificar para el extremo flexible (por defecto) o el rígido del rango de rigidez de una máquina no medida.</translation>
    </message>
    <message>
        <source>--machine-end is compliant or stiff, not &quot;%1&quot;</source>
        <translation>--machine-end es compliant o stiff, no «%1»</translation>
    </message>
    <message>
        <source>%1: unknown command &apos;%2&apos;.</source>
        <translation>%1: orden desconocida &apos;%2&apos;.</translation>
    </message>
    <message>
        <source>Did you mean &apos;%1&apos;?</source>
        <translation>¿Quería decir &apos;%1&apos;?</translation>
    </message>
    <message>
        <source>Run &apos;%1 --help&apos; for the list of commands.</source>
        <translation>Ejecute &apos;%1 --help&apos; para ver la lista de órdenes.</translation>
    </message>
    <message>
        <source>The planner&apos;s name for the title block.</source>
        <translation>El nombre del planificador para el cajetín.</translation>
    </message>
    <message>
        <source>cannot write to standard output: %1</source>
        <translation>no se puede escribir en la salida estándar: %1</translation>
    </message>
    <message>
        <source>PDF file to write (&apos;-&apos;: standard output).</source>
        <translation>Archivo PDF que escribir (&apos;-&apos;: salida estándar).</translation>
    </message>
    <message>
        <source>part &quot;%1&quot;, %2 mm long, %3 outer and %4 inner features, %5, %6, %7</source>
        <translation>pieza «%1», %2 mm de largo, %3 elementos exteriores y %4 interiores, %5, %6, %7</translation>
    </message>
    <message numerus="yes">
        <source>%n pass(es)</source>
        <translation>
            <numerusform>%n pasada</numerusform>
            <numerusform>%n pasadas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n tolerance(s)</source>
        <translation>
            <numerusform>%n tolerancia</numerusform>
            <numerusform>%n tolerancias</numerusform>
        </translation>
    </message>
    <message>
        <source>the result is not finite at &apos;%1&apos;: the inputs lie beyond what the model computes (see the input bounds in docs/project-format.md)</source>
        <translation>el resultado no es finito en &apos;%1&apos;: los datos quedan fuera de lo que el modelo calcula (vea los límites de entrada en docs/project-format.md)</translation>
    </message>
    <message>
        <source>--load takes three numbers in newtons, radial,tangential,axial (e.g. 200,500,150), each at most 1e6, not &quot;%1&quot;</source>
        <translation>--load toma tres números en newtons, radial,tangencial,axial (p. ej. 200,500,150), cada uno como mucho 1e6, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>--stations %1 on %2 features makes %3 tool positions, more than the %4 computed at once; give at most %5</source>
        <translation>--stations %1 en %2 elementos da %3 posiciones de la herramienta, más que las %4 que se calculan de una vez; indique como mucho %5</translation>
    </message>
    <message>
        <source>Best plan (%1) found within the time limit</source>
        <translation>Mejor plan (%1) hallado dentro del límite de tiempo</translation>
    </message>
    <message>
        <source>Stop the search after SECONDS (0.01 to 3600, default 60) with the best plan found by then.</source>
        <translation>Detener la búsqueda tras SECONDS (0,01 a 3600, por defecto 60) con el mejor plan hallado hasta entonces.</translation>
    </message>
    <message>
        <source>--time-limit is from 0.01 to 3600 seconds, not &quot;%1&quot;</source>
        <translation>--time-limit va de 0,01 a 3600 segundos, no «%1»</translation>
    </message>
    <message>
        <source>Learn what a machine&apos;s measured parts show beyond the physics (Li &amp; Du): geometric error, hybrid RBF network, and how well parts not learned from are predicted with and without it.</source>
        <translation>Aprender lo que las piezas medidas de una máquina muestran más allá de la física (Li &amp; Du): error geométrico, red RBF híbrida y lo bien que se predicen piezas no aprendidas con y sin ella.</translation>
    </message>
    <message>
        <source>With what was learned of %1 (model %2, %3 parts; parts left out predicted to %4 µm RMS, the physics alone %5 µm):</source>
        <translation>Con lo aprendido de %1 (modelo %2, %3 piezas; piezas dejadas fuera predichas a %4 µm RMS, la física sola %5 µm):</translation>
    </message>
    <message>
        <source>radius error %1 … %2 µm</source>
        <translation>error de radio %1 … %2 µm</translation>
    </message>
    <message>
        <source>Add what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Añadir lo aprendido de la máquina a partir de sus piezas medidas (learn --save).</translation>
    </message>
    <message>
        <source>The measurement store: an SQLite file, or postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).</source>
        <translation>El almacén de mediciones: un archivo SQLite o postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (por defecto: %1).</translation>
    </message>
    <message>
        <source>Machine: learned from measured parts (%1); parts left out were predicted to %2 µm RMS, the physics alone to %3 µm</source>
        <translation>Máquina: aprendida de piezas medidas (%1); las piezas dejadas fuera se predijeron a %2 µm RMS, la física sola a %3 µm</translation>
    </message>
    <message>
        <source>Judge with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Juzgar con lo aprendido de la máquina a partir de sus piezas medidas (learn --save).</translation>
    </message>
    <message>
        <source>Plan with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Planificar con lo aprendido de la máquina a partir de sus piezas medidas (learn --save).</translation>
    </message>
    <message>
        <source>--learned replaces the stiffness range: give it or --machine-end, not both</source>
        <translation>--learned sustituye al rango de rigidez: indique esta opción o --machine-end, no ambas</translation>
    </message>
    <message>
        <source>Base the report on what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Basar el informe en lo aprendido de la máquina a partir de sus piezas medidas (learn --save).</translation>
    </message>
    <message>
        <source>The operation (set-up) to work on, by its name (default: the first).</source>
        <translation>La operación (montaje) con la que trabajar, por su nombre (por defecto: la primera).</translation>
    </message>
    <message>
        <source>--operation: the project has no operation &quot;%1&quot;; it has: %2</source>
        <translation>--operation: el proyecto no tiene ninguna operación &quot;%1&quot;; tiene: %2</translation>
    </message>
    <message>
        <source>the project has %1 operations (%2); this is %3 (--operation NAME for another)</source>
        <translation>el proyecto tiene %1 operaciones (%2); esta es %3 (--operation NAME para otra)</translation>
    </message>
    <message>
        <source>%1 (operation %2 of %3): %4, the %5 end held</source>
        <translation>%1 (operación %2 de %3): %4, extremo %5 sujetado</translation>
    </message>
    <message>
        <source>%1 (%2, %3 end held)</source>
        <translation>%1 (%2, extremo %3 sujetado)</translation>
    </message>
    <message numerus="yes">
        <source>; %n set-up(s): </source>
        <translation>
            <numerusform>; %n montaje: </numerusform>
            <numerusform>; %n montajes: </numerusform>
        </translation>
    </message>
    <message>
        <source>Split into operations: %1 (Edit &gt; Operations…, or further_operations in the file)</source>
        <translation>Dividir en operaciones: %1 (Editar &gt; Operaciones…, o further_operations en el archivo)</translation>
    </message>
    <message>
        <source>collet stiffness needed: %1</source>
        <translation>rigidez necesaria de la pinza: %1</translation>
    </message>
    <message>
        <source>Plain Timoshenko beam: without the corrections for the root in the jaws and the shoulders identified from solid FE.</source>
        <translation>Viga de Timoshenko sin más: sin las correcciones del empotramiento en las garras y de los resaltes identificadas con EF sólidos.</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a number from %3 to %4</source>
        <translation>--%1: «%2» no es un número de %3 a %4</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a whole number from %3 to %4</source>
        <translation>--%1: «%2» no es un número entero de %3 a %4</translation>
    </message>
    <message numerus="yes">
        <source>, %n milled feature(s)</source>
        <translation>
            <numerusform>, %n elemento fresado</numerusform>
            <numerusform>, %n elementos fresados</numerusform>
        </translation>
    </message>
    <message>
        <source>Number of the pass, 1 for the first (default: the last finishing pass).</source>
        <translation>Número de la pasada, 1 para la primera (por defecto: la última pasada de acabado).</translation>
    </message>
    <message>
        <source>--pass must be a pass number (1, 2, …), not &quot;%1&quot;</source>
        <translation>--pass debe ser un número de pasada (1, 2, …), no «%1»</translation>
    </message>
    <message>
        <source>warning: %1: dropped with the passes it was on</source>
        <translation>aviso: %1: eliminado con las pasadas en las que estaba</translation>
    </message>
    <message>
        <source>the output &apos;%1&apos; is the input file &apos;%2&apos;: give another output file, so that the input is not overwritten</source>
        <translation>la salida &apos;%1&apos; es el archivo de entrada &apos;%2&apos;: indique otro archivo de salida para que la entrada no se sobrescriba</translation>
    </message>
    <message>
        <source>there is no measurement store %1: &apos;measurements add&apos; stores the first part in it</source>
        <translation>no hay ningún almacén de mediciones %1: &apos;measurements add&apos; guarda en él la primera pieza</translation>
    </message>
    <message>
        <source>the output &apos;%1&apos; is the measurement store &apos;%2&apos;: give another output file, so that the store is not overwritten</source>
        <translation>la salida &apos;%1&apos; es el almacén de mediciones &apos;%2&apos;: indique otro archivo de salida para que el almacén no se sobrescriba</translation>
    </message>
    <message>
        <source>%1 × %2 window, %3 % feasible; %4</source>
        <translation>ventana de %1 × %2, %3 % factible; %4</translation>
    </message>
    <message>
        <source>%1%2: the value is empty; give one, or leave the option out for its default</source>
        <translation>%1%2: el valor está vacío; indique uno, u omita la opción para su valor predeterminado</translation>
    </message>
    <message>
        <source>  to meet it: </source>
        <translation>  para cumplirla: </translation>
    </message>
    <message numerus="yes">
        <source>  roughing: %n pass(es) of ap %1 mm at vc %2 m/min, f %3 mm/rev</source>
        <translation>
            <numerusform>  desbaste: %n pasada de ap %1 mm a vc %2 m/min, f %3 mm/rev</numerusform>
            <numerusform>  desbaste: %n pasadas de ap %1 mm a vc %2 m/min, f %3 mm/rev</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>wrote %1: %n pass(es)</source>
        <translation>
            <numerusform>se ha escrito %1: %n pasada</numerusform>
            <numerusform>se ha escrito %1: %n pasadas</numerusform>
        </translation>
    </message>
    <message>
        <source>Boring bar %1 (%2): Fc = %3 N, Ff = %4 N, Fp = %5 N; tip compliance %6 µm/N; Ra %7 µm, Rz %8 µm</source>
        <translation>Barra de mandrinar %1 (%2): Fc = %3 N, Ff = %4 N, Fp = %5 N; flexibilidad en la punta %6 µm/N; Ra %7 µm, Rz %8 µm</translation>
    </message>
    <message>
        <source>  time per part %1 min (finishing %2, roughing %3, handling %4, tool changes %5), cost %6 at %7 per min, %8</source>
        <translation>  tiempo por pieza %1 min (acabado %2, desbaste %3, manipulación %4, cambios de herramienta %5), coste %6 a %7 por min, %8</translation>
    </message>
    <message>
        <source>%1 tool edges per part</source>
        <translation>%1 filos de herramienta por pieza</translation>
    </message>
    <message>
        <source>tool edges per part not known (no tool life)</source>
        <translation>filos de herramienta por pieza desconocidos (sin vida de herramienta)</translation>
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
        <translation>óptimo en f = %1 mm/rev, %2</translation>
    </message>
    <message>
        <source>no plan meets every constraint; the one that violates them least at f = %1 mm/rev, %2</source>
        <translation>ningún plan cumple todas las restricciones; el que menos las incumple, en f = %1 mm/rev, %2</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>desconocido</translation>
    </message>
</context>
<context>
    <name>Compensation</name>
    <message>
        <source>the face&apos;s conicity needs a correction along Z, which TolTurn does not generate: reduce the feed or change the clamping</source>
        <translation>la conicidad de la cara requiere una corrección en Z, que TolTurn no genera: reduzca el avance o cambie la sujeción</translation>
    </message>
    <message>
        <source>%1: the correction, %2 µm, is larger than the finishing depth of cut %3 mm: the prediction, made for that depth, does not hold there and the correction is not a program to run; support the part (tailstock, steady rest), cut less or check the machine&apos;s data</source>
        <translation>%1: la corrección, %2 µm, es mayor que la profundidad de corte de acabado %3 mm: la predicción, hecha para esa profundidad, no vale ahí y la corrección no es un programa que se pueda ejecutar; apoye la pieza (contrapunto, luneta), corte menos o revise los datos de la máquina</translation>
    </message>
</context>
<context>
    <name>ControlCommand</name>
    <message>
        <source>roughing</source>
        <translation>desbaste</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>acabado</translation>
    </message>
    <message>
        <source>%1: constant-force control, adaptive against the programmed feed</source>
        <translation>%1: control de fuerza constante, adaptativo frente al avance programado</translation>
    </message>
    <message>
        <source>Pass %1 (%2): f %3 mm/rev, a_p %4 mm, vc %5 m/min; set force %6 N (F ∝ f^%7)</source>
        <translation>Pasada %1 (%2): f %3 mm/rev, a_p %4 mm, vc %5 m/min; fuerza de consigna %6 N (F ∝ f^%7)</translation>
    </message>
    <message>
        <source>constant feed</source>
        <translation>avance constante</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptativo</translation>
    </message>
    <message>
        <source>time in cut [s]</source>
        <translation>tiempo en corte [s]</translation>
    </message>
    <message>
        <source>%1 (%2 %)</source>
        <translation>%1 (%2 %)</translation>
    </message>
    <message>
        <source>peak force [N]</source>
        <translation>fuerza máxima [N]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>avance [mm/rev]</translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation>desviación [µm]</translation>
    </message>
    <message>
        <source>largest Ra [µm]</source>
        <translation>Ra máxima [µm]</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>nota: %1</translation>
    </message>
    <message>
        <source>Constant-force adaptive control of the plan&apos;s passes (Čuš &amp; Župerl): the feed override commanded every 20 ms through the feed drive&apos;s dynamics, against the programmed feed: time, peak force, feed, deviation and roughness along the pass.</source>
        <translation>Control adaptativo de fuerza constante de las pasadas del plan (Čuš &amp; Župerl): el override de avance ordenado cada 20 ms a través de la dinámica del accionamiento de avance, frente al avance programado: tiempo, fuerza máxima, avance, desviación y rugosidad a lo largo de la pasada.</translation>
    </message>
    <message>
        <source>Print a summary per pass as JSON.</source>
        <translation>Imprimir un resumen por pasada en JSON.</translation>
    </message>
    <message>
        <source>Print every control period of both runs as CSV.</source>
        <translation>Imprimir cada periodo de control de ambas simulaciones en CSV.</translation>
    </message>
    <message>
        <source>Only pass N of the plan (1, 2, …).</source>
        <translation>Solo la pasada N del plan (1, 2, …).</translation>
    </message>
    <message>
        <source>The resultant force to hold in N (default: the programmed feed&apos;s at the pass&apos;s depth).</source>
        <translation>La fuerza resultante a mantener en N (por defecto: la del avance programado a la profundidad de la pasada).</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force in % (default 0).</source>
        <translation>Ruido de máquina: desviación típica de la fuerza medida en % (por defecto 0).</translation>
    </message>
    <message>
        <source>Seed of the noise (default 1).</source>
        <translation>Semilla del ruido (por defecto 1).</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>El archivo de proyecto.</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>indique --json o --csv, no ambos</translation>
    </message>
    <message>
        <source>Weight of each period&apos;s estimate of the process gain, %1–%2 (default 1; tune-control finds it).</source>
        <translation>Peso de la estimación de la ganancia del proceso en cada periodo, %1–%2 (por defecto 1; tune-control lo determina).</translation>
    </message>
    <message>
        <source>Share of the step to the set force&apos;s feed commanded each period, %1–%2 (default 1).</source>
        <translation>Fracción del paso hacia el avance de la fuerza de consigna que se ordena en cada periodo, %1–%2 (por defecto 1).</translation>
    </message>
    <message>
        <source>%1: controller tuning on pass %2, RMS of F / F_set − 1 over the cut</source>
        <translation>%1: ajuste del controlador en la pasada %2, valor eficaz de F / F_consigna − 1 sobre el corte</translation>
    </message>
    <message>
        <source>untuned (both gains 1): %1 %</source>
        <translation>sin ajustar (ambas ganancias 1): %1 %</translation>
    </message>
    <message>
        <source>method</source>
        <translation>método</translation>
    </message>
    <message>
        <source>estimator</source>
        <translation>estimador</translation>
    </message>
    <message>
        <source>command</source>
        <translation>orden</translation>
    </message>
    <message>
        <source>RMS [%]</source>
        <translation>valor eficaz [%]</translation>
    </message>
    <message>
        <source>evaluations</source>
        <translation>evaluaciones</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>tiempo [s]</translation>
    </message>
    <message>
        <source>--methods: &quot;%1&quot; is not a method (%2)</source>
        <translation>--methods: «%1» no es un método (%2)</translation>
    </message>
    <message>
        <source>Tune the constant-force controller on a pass of the plan (the estimator&apos;s and the command&apos;s gains): particle swarm (Čuš &amp; Župerl&apos;s method, pagmo2) against NLopt&apos;s algorithms on the same objective.</source>
        <translation>Ajustar el controlador de fuerza constante en una pasada del plan (las ganancias del estimador y de la orden): enjambre de partículas (el método de Čuš y Župerl, pagmo2) frente a los algoritmos de NLopt sobre el mismo objetivo.</translation>
    </message>
    <message>
        <source>Print the comparison as JSON.</source>
        <translation>Mostrar la comparación como JSON.</translation>
    </message>
    <message>
        <source>Comma-separated methods (default all: %1).</source>
        <translation>Métodos separados por comas (por defecto todos: %1).</translation>
    </message>
    <message>
        <source>--methods: no method named</source>
        <translation>--methods: no se indica ningún método</translation>
    </message>
    <message>
        <source>Simulations of the pass each method may ask for, at least %1 (default 400).</source>
        <translation>Simulaciones de la pasada que puede pedir cada método, al menos %1 (por defecto 400).</translation>
    </message>
</context>
<context>
    <name>ControlExample</name>
    <message>
        <source>Čuš &amp; Župerl&apos;s end-milling system rebuilt (docs/adaptive.md §9)</source>
        <translation>El sistema de fresado frontal de Čuš y Župerl reconstruido (docs/adaptive.md §9)</translation>
    </message>
    <message>
        <source>Cut data: mean forces of the linear edge-force model (Altintas 2012 §2.4), Al7075-T6, carbide, dry: Ktc %1, Krc %2, Kac %3 N/mm², Kte %4, Kre %5, Kae %6 N/mm (CJME 2021, doi:10.1186/s10033-021-00536-9, table 5); 004 gives neither its data nor its material.</source>
        <translation>Datos de corte: fuerzas medias del modelo lineal de fuerzas de filo (Altintas 2012 §2.4), Al7075-T6, metal duro, en seco: Ktc %1, Krc %2, Kac %3 N/mm², Kte %4, Kre %5, Kae %6 N/mm (CJME 2021, doi:10.1186/s10033-021-00536-9, tabla 5); 004 no da ni sus datos ni su material.</translation>
    </message>
    <message>
        <source>Tool and cut: Ø%1 mm, %2 flutes, down milling, radial depth %3 mm; axial depth %4 mm, at which the model gives the paper&apos;s 181.1 N at 324.61 mm/min and 2201 1/min.</source>
        <translation>Herramienta y corte: Ø%1 mm, %2 filos, fresado en concordancia, profundidad radial %3 mm; profundidad axial %4 mm, a la que el modelo da los 181,1 N del artículo a 324,61 mm/min y 2201 1/min.</translation>
    </message>
    <message>
        <source>Network 8–15–3, ArcTangent, max–min normalised, back-propagation (learning rate 0.05, momentum 0.008, 2000 epochs) on 441 cut points: %1 % RMS error on the 400 between them.</source>
        <translation>Red 8–15–3, arcotangente, normalizada máx.–mín., retropropagación (tasa de aprendizaje 0,05, momento 0,008, 2000 épocas) en 441 puntos de corte: %1 % de error eficaz en los 400 intermedios.</translation>
    </message>
    <message>
        <source>Off-line PSO-NN: the largest feed rate within %1 N by the network (%2–%3 mm/min, %4–%5 1/min)</source>
        <translation>PSO-NN fuera de línea: la mayor velocidad de avance dentro de %1 N según la red (%2–%3 mm/min, %4–%5 1/min)</translation>
    </message>
    <message numerus="yes">
        <source>%n evaluation(s) of the network</source>
        <translation>
            <numerusform>%n evaluación de la red</numerusform>
            <numerusform>%n evaluaciones de la red</numerusform>
        </translation>
    </message>
    <message>
        <source>The loop, table 1 simulation 5: from %1 mm/min and %2 1/min, set force %3 N, %4 s</source>
        <translation>El lazo, tabla 1 simulación 5: desde %1 mm/min y %2 1/min, fuerza de consigna %3 N, %4 s</translation>
    </message>
    <message>
        <source>uncontrolled</source>
        <translation>sin control</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptativo</translation>
    </message>
    <message>
        <source>paper</source>
        <translation>artículo</translation>
    </message>
    <message>
        <source>Table 1, every row from its conditions to its force: settled against the paper</source>
        <translation>Tabla 1, cada fila desde sus condiciones hasta su fuerza: estabilizado frente al artículo</translation>
    </message>
    <message>
        <source>  * outside the network&apos;s training range: it extrapolates there</source>
        <translation>  * fuera del rango de entrenamiento de la red: allí extrapola</translation>
    </message>
    <message>
        <source>note: Ra from the printed M5 (eq. 6), which does not reproduce the paper&apos;s table (docs/adaptive.md §2). The spindle follows eq. 1 too: 004 gives no spindle model.</source>
        <translation>nota: Ra del M5 impreso (ec. 6), que no reproduce la tabla del artículo (docs/adaptive.md §2). El husillo sigue también la ec. 1: 004 no da modelo del husillo.</translation>
    </message>
    <message>
        <source>Čuš &amp; Župerl&apos;s own end-milling system rebuilt: the force network trained on cut data, the off-line PSO-NN optimisation, the loop overriding feed and spindle speed, beside the paper&apos;s table 1.</source>
        <translation>El propio sistema de fresado frontal de Čuš y Župerl reconstruido: la red de fuerzas entrenada con datos de corte, la optimización PSO-NN fuera de línea, el lazo que corrige avance y velocidad del husillo, junto a la tabla 1 del artículo.</translation>
    </message>
    <message>
        <source>Print the results as JSON.</source>
        <translation>Mostrar los resultados como JSON.</translation>
    </message>
    <message>
        <source>Print every control period of both runs as CSV.</source>
        <translation>Mostrar cada periodo de control de ambas ejecuciones como CSV.</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force in % (default 0).</source>
        <translation>Ruido de máquina: desviación típica de la fuerza medida en % (por defecto 0).</translation>
    </message>
    <message>
        <source>Seed of the noise (default 1).</source>
        <translation>Semilla del ruido (por defecto 1).</translation>
    </message>
    <message>
        <source>Share of a change of chip load the spindle speed takes, 0–1 (default 0.5).</source>
        <translation>Fracción de un cambio del espesor de viruta que asume la velocidad del husillo, 0–1 (por defecto 0,5).</translation>
    </message>
    <message>
        <source>Simulated time in s, 0.1–60 (default 3).</source>
        <translation>Tiempo simulado en s, 0,1–60 (por defecto 3).</translation>
    </message>
    <message>
        <source>takes no file: &quot;%1&quot;</source>
        <translation>no admite archivo: «%1»</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>indique --json o --csv, no ambos</translation>
    </message>
</context>
<context>
    <name>CurrentForces</name>
    <message>
        <source>%1 = %2 is outside the range %3 to %4 of the calibration cuts: the network extrapolates</source>
        <translation>%1 = %2 está fuera del intervalo de %3 a %4 de los cortes de calibración: la red extrapola</translation>
    </message>
    <message>
        <source>a force, the chip area or an angle is not a finite number</source>
        <translation>una fuerza, la sección de viruta o un ángulo no es un número finito</translation>
    </message>
    <message>
        <source>the uncut chip area A_c = %1 mm² (eq. 16) is not above zero</source>
        <translation>la sección de viruta sin deformar A_c = %1 mm² (ec. 16) no es mayor que cero</translation>
    </message>
    <message>
        <source>eq. 17 and 18 do not determine K_n and K_f for back rake %1°, normal rake %2° and effective lead angle %3° (determinant %4)</source>
        <translation>las ec. 17 y 18 no determinan K_n y K_f para un ángulo de inclinación posterior de %1°, un ángulo de desprendimiento normal de %2° y un ángulo de posición efectivo de %3° (determinante %4)</translation>
    </message>
    <message>
        <source>F_t = %1 N and F_a = %2 N give a normal pressure K_n = %3 N/mm² that is not positive (eq. 17–18): check the forces and the tool angles</source>
        <translation>F_t = %1 N y F_a = %2 N dan una presión normal K_n = %3 N/mm² que no es positiva (ec. 17–18): compruebe las fuerzas y los ángulos de la herramienta</translation>
    </message>
    <message>
        <source>%1 = %2 is not above zero</source>
        <translation>%1 = %2 no es mayor que cero</translation>
    </message>
    <message>
        <source>the nose radius %1 mm is negative or not a number</source>
        <translation>el radio de punta %1 mm es negativo o no es un número</translation>
    </message>
    <message>
        <source>%1 = %2° is not between %3° and %4°</source>
        <translation>%1 = %2° no está entre %3° y %4°</translation>
    </message>
    <message>
        <source>the current–force model has not been trained</source>
        <translation>el modelo corriente-fuerza no se ha entrenado</translation>
    </message>
    <message>
        <source>the radial force cannot be found from the estimated F_t = %1 N and F_a = %2 N: %3</source>
        <translation>no se puede obtener la fuerza radial a partir de las estimaciones F_t = %1 N y F_a = %2 N: %3</translation>
    </message>
    <message>
        <source>the friction ratio K_f = %1 found from F_t = %2 N and F_a = %3 N is negative: the friction on the rake face would push the chip down it</source>
        <translation>la relación de fricción K_f = %1 obtenida de F_t = %2 N y F_a = %3 N es negativa: la fricción en la cara de desprendimiento empujaría la viruta hacia abajo por ella</translation>
    </message>
    <message>
        <source>samples: %1 calibration cuts; at least %2 are needed (the paper trained on 21)</source>
        <translation>muestras: %1 cortes de calibración; se necesitan al menos %2 (el artículo entrenó con 21)</translation>
    </message>
    <message>
        <source>the measured tangential force is not a finite number</source>
        <translation>la fuerza tangencial medida no es un número finito</translation>
    </message>
    <message>
        <source>the measured axial force is not a finite number</source>
        <translation>la fuerza axial medida no es un número finito</translation>
    </message>
    <message>
        <source>tangential network (eq. 11): %1</source>
        <translation>red de la fuerza tangencial (ec. 11): %1</translation>
    </message>
    <message>
        <source>axial network (eq. 13): %1</source>
        <translation>red de la fuerza axial (ec. 13): %1</translation>
    </message>
    <message>
        <source>the current–force model has no valid &quot;%1&quot;</source>
        <translation>el modelo corriente-fuerza no tiene un «%1» válido</translation>
    </message>
</context>
<context>
    <name>CuttingModels</name>
    <message>
        <source>%1 = %2 is outside the range %3 &lt; %1 &lt; %4 in which %5 is stated to hold</source>
        <translation>%1 = %2 está fuera del intervalo %3 &lt; %1 &lt; %4 para el que se declara la validez de %5</translation>
    </message>
    <message>
        <source>chip thickness h = f sin(kappa_r) = %1 mm is outside the range %2–%3 mm over which the Kienzle constants of this material were measured</source>
        <translation>el espesor de viruta h = f sin(kappa_r) = %1 mm está fuera del intervalo %2–%3 mm en el que se midieron las constantes de Kienzle de este material</translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002)</source>
        <translation>ec. 20 de Li &amp; Du (2002)</translation>
    </message>
    <message>
        <source>lead angle [°]</source>
        <translation>ángulo de entrada [°]</translation>
    </message>
    <message>
        <source>depth of cut [mm]</source>
        <translation>profundidad de corte [mm]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>avance [mm/rev]</translation>
    </message>
    <message>
        <source>nose radius [mm]</source>
        <translation>radio de punta [mm]</translation>
    </message>
    <message>
        <source>eq. 20 of Li &amp; Du (2002) needs a nose radius larger than the feed, but r_n = %1 mm and f = %2 mm/rev</source>
        <translation>la ec. 20 de Li &amp; Du (2002) requiere un radio de punta mayor que el avance, pero r_n = %1 mm y f = %2 mm/rev</translation>
    </message>
    <message>
        <source>no force measurements given</source>
        <translation>no se han indicado mediciones de fuerza</translation>
    </message>
    <message>
        <source>the measurements do not determine K_n and K_f (rank %1 of 2)</source>
        <translation>las mediciones no determinan K_n y K_f (rango %1 de 2)</translation>
    </message>
    <message>
        <source>the fitted normal pressure K_n = %1 N/mm² is not positive: check the measured forces and the tool angles</source>
        <translation>la presión normal ajustada K_n = %1 N/mm² no es positiva: compruebe las fuerzas medidas y los ángulos de la herramienta</translation>
    </message>
</context>
<context>
    <name>DataFiles</name>
    <message>
        <source>cannot open the data file: %1</source>
        <translation>no se puede abrir el archivo de datos: %1</translation>
    </message>
    <message>
        <source>not a valid JSON object: %1</source>
        <translation>no es un objeto JSON válido: %1</translation>
    </message>
    <message>
        <source>expected format &quot;%1&quot; version 1</source>
        <translation>se esperaba el formato &quot;%1&quot; versión 1</translation>
    </message>
    <message>
        <source>required value is missing</source>
        <translation>falta un valor obligatorio</translation>
    </message>
    <message>
        <source>expected {&quot;value&quot;: number, &quot;source&quot;: key of &quot;sources&quot;}</source>
        <translation>se esperaba {&quot;value&quot;: número, &quot;source&quot;: clave de &quot;sources&quot;}</translation>
    </message>
    <message>
        <source>material &quot;%1&quot; lacks its id, modulus, density or Kienzle constants</source>
        <translation>al material &quot;%1&quot; le falta el id, el módulo, la densidad o las constantes de Kienzle</translation>
    </message>
    <message>
        <source>a stiffness range needs 0 &lt; compliant &lt;= stiff, not %1 and %2</source>
        <translation>un rango de rigidez necesita 0 &lt; flexible &lt;= rígido, no %1 y %2</translation>
    </message>
    <message>
        <source>a boring-bar material needs its type letters, modulus, Poisson&apos;s ratio and largest overhang ratio</source>
        <translation>un material de barra de mandrinar necesita sus letras de tipo, módulo de elasticidad, coeficiente de Poisson y mayor relación de voladizo</translation>
    </message>
</context>
<context>
    <name>DeviationModel</name>
    <message>
        <source>Feed and passive force from the rule of thumb Ff = %1 Fc, Fp = %2 Fc (%3): the material data give no feed or passive force constants. Calibrate the forces for accuracy.</source>
        <translation>Fuerza de avance y fuerza pasiva según la regla empírica Ff = %1 Fc, Fp = %2 Fc (%3): los datos del material no incluyen constantes de fuerza de avance ni de fuerza pasiva. Calibre las fuerzas para mayor precisión.</translation>
    </message>
    <message>
        <source>no source: zero</source>
        <translation>sin fuente: cero</translation>
    </message>
    <message>
        <source>Toolpost shortening not included: holder &quot;%1&quot; is not in the data library.</source>
        <translation>No se incluye el acortamiento de la torreta: el portaherramientas &quot;%1&quot; no está en la biblioteca de datos.</translation>
    </message>
    <message>
        <source>Workpiece only: machine supports rigid, no toolpost or thermal term.</source>
        <translation>Solo la pieza: apoyos de la máquina rígidos, sin término de torreta ni térmico.</translation>
    </message>
    <message>
        <source>unknown material &quot;%1&quot;; the data library has: %2</source>
        <translation>material desconocido &quot;%1&quot;; la biblioteca de datos contiene: %2</translation>
    </message>
    <message>
        <source>material &quot;%1&quot; has no Poisson&apos;s ratio in the data, which the shear deflection needs</source>
        <translation>el material &quot;%1&quot; no tiene coeficiente de Poisson en los datos, necesario para la flexión por cortante</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library and its ISO 5608 style letter (third character) gives no known entering angle</source>
        <translation>el portaherramientas &quot;%1&quot; no está en la biblioteca de datos y su letra de forma ISO 5608 (tercer carácter) no corresponde a ningún ángulo de posición conocido</translation>
    </message>
    <message>
        <source>the Li &amp; Du model needs the rake and inclination angles of the tool; the data give none for holder &quot;%1&quot; with insert &quot;%2&quot;: set tool.rake_deg and tool.inclination_deg</source>
        <translation>el modelo de Li &amp; Du necesita los ángulos de desprendimiento y de inclinación de la herramienta; los datos no los incluyen para el portaherramientas &quot;%1&quot; con la plaquita &quot;%2&quot;: defina tool.rake_deg y tool.inclination_deg</translation>
    </message>
    <message>
        <source>the force model needs a known material and holder</source>
        <translation>el modelo de fuerzas necesita un material y un portaherramientas conocidos</translation>
    </message>
    <message>
        <source>there is no cutting pass; the deviation is that of the pass that finishes the features</source>
        <translation>no hay ninguna pasada de corte; la desviación es la de la pasada que acaba los elementos</translation>
    </message>
    <message>
        <source>unknown machine &quot;%1&quot;; the data library has: %2</source>
        <translation>máquina desconocida &quot;%1&quot;; la biblioteca de datos contiene: %2</translation>
    </message>
    <message>
        <source>the %1 clamping with these supports leaves the part free to move</source>
        <translation>la sujeción (%1) con estos apoyos deja la pieza libre para moverse</translation>
    </message>
    <message>
        <source>Thermal drift not characterised for this machine: taken as zero.</source>
        <translation>Deriva térmica no caracterizada para esta máquina: se considera nula.</translation>
    </message>
    <message>
        <source>the pass needs %1 kW of cutting power, more than the machine&apos;s %2 kW</source>
        <translation>la pasada requiere %1 kW de potencia de corte, más que los %2 kW de la máquina</translation>
    </message>
    <message>
        <source>compliant</source>
        <translation>flexible</translation>
    </message>
    <message>
        <source>stiff</source>
        <translation>rígido</translation>
    </message>
    <message>
        <source>Spindle–chuck not measured: a radial spring of %1 N/µm at the chuck face, the %2 end of the published range %3–%4 N/µm (%5); no tilt of the chuck. A test-bar fit (Valiño et al. 2008 §III) replaces it.</source>
        <translation>Husillo–plato no medido: un muelle radial de %1 N/µm en la cara del plato, el extremo %2 del rango publicado %3–%4 N/µm (%5); sin giro del plato. Un ajuste a una barra de prueba (Valiño et al. 2008 §III) lo sustituye.</translation>
    </message>
    <message>
        <source>Spindle–chuck neither measured nor in the data: taken as rigid, which is optimistic. Measure k1, k2, k3 (Valiño et al. 2008 §III).</source>
        <translation>Husillo–plato ni medido ni en los datos: se toma como rígido, lo que es optimista. Mida k1, k2, k3 (Valiño et al. 2008 §III).</translation>
    </message>
    <message>
        <source>%1 not measured and no published stiffness found: taken as a rigid pin, which is optimistic. The verdicts give the stiffness each tolerance needs of it.</source>
        <translation>%1 no medido y sin rigidez publicada: se toma como un apoyo rígido, lo que es optimista. Los veredictos dan la rigidez que cada tolerancia necesita de él.</translation>
    </message>
    <message>
        <source>Headstock centre</source>
        <translation>Punto del cabezal</translation>
    </message>
    <message>
        <source>Tailstock</source>
        <translation>Contrapunto</translation>
    </message>
    <message>
        <source>given forces</source>
        <translation>fuerzas dadas</translation>
    </message>
    <message>
        <source>Toolpost: the whole holder length (%1 mm) is taken in compression, an upper bound; enter the tool&apos;s overhang (the length out of the turret) to replace it.</source>
        <translation>Portaherramientas: se toma toda la longitud del portaherramientas (%1 mm) a compresión, una cota superior; introduzca el voladizo de la herramienta (la longitud fuera de la torreta) para sustituirla.</translation>
    </message>
    <message>
        <source>the predicted deflection, %1 mm at z = %2 mm, is larger than the depth of cut %3 mm: the part would spring out of the cut, and a model linear in the forces of the nominal depth does not hold; support the part (tailstock, steady rest) or cut less</source>
        <translation>la flexión prevista, %1 mm en z = %2 mm, es mayor que la profundidad de corte %3 mm: la pieza se saldría del corte, y un modelo lineal en las fuerzas de la profundidad nominal no vale; apoye la pieza (contrapunto, luneta) o corte menos</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar in the data library</source>
        <translation>&quot;%1&quot; no es una barra de mandrinar de la biblioteca de datos</translation>
    </message>
    <message>
        <source>the bar material of &quot;%1&quot; (type letter %2) is not in the data library: its stiffness is unknown</source>
        <translation>el material de la barra de &quot;%1&quot; (letra de tipo %2) no está en la biblioteca de datos: se desconoce su rigidez</translation>
    </message>
    <message>
        <source>an overhang of %1 mm does not reach the bottom of the bore, %2 mm in from the right end face</source>
        <translation>un voladizo de %1 mm no llega al fondo del agujero, a %2 mm de la cara frontal derecha</translation>
    </message>
    <message>
        <source>an overhang of %1 mm is longer than the bar &quot;%2&quot; itself (%3 mm)</source>
        <translation>un voladizo de %1 mm es más largo que la propia barra &quot;%2&quot; (%3 mm)</translation>
    </message>
    <message>
        <source>Boring bar %1: %2, Ø%3 mm, %4 mm overhang (L/D %5), E = %6 GPa (%7).</source>
        <translation>Barra de mandrinar %1: %2, Ø%3 mm, %4 mm de voladizo (L/D %5), E = %6 GPa (%7).</translation>
    </message>
    <message>
        <source>The cutting edge&apos;s offset from the bar axis (the maker&apos;s f) not given: taken as the bar&apos;s radius, %1 mm, the least it can be; the twist of the bar and the moment of the feed force grow with it.</source>
        <translation>Desplazamiento del filo respecto al eje de la barra (la cota f del fabricante) no indicado: se toma el radio de la barra, %1 mm, el mínimo posible; la torsión de la barra y el momento de la fuerza de avance crecen con él.</translation>
    </message>
    <message>
        <source>Boring bar %1 has a coolant bore the designation does not size: computed as a solid bar, which underestimates its deflection.</source>
        <translation>La barra de mandrinar %1 tiene un conducto de refrigerante cuyo tamaño no indica la designación: se calcula como barra maciza, lo que subestima su flexión.</translation>
    </message>
    <message>
        <source>No boring bar given: the bores are computed as if cut by the turning tool %1, without the bending of a bar, which in a bore is often the largest term.</source>
        <translation>No se ha indicado barra de mandrinar: los agujeros se calculan como si los mecanizara la herramienta de torneado %1, sin la flexión de una barra, que en un agujero suele ser el término mayor.</translation>
    </message>
    <message>
        <source>%1, operation %2 of %3: the part held at its %4 end, z from that end.</source>
        <translation>%1, operación %2 de %3: la pieza sujetada por su extremo %4, z desde ese extremo.</translation>
    </message>
    <message>
        <source>The outer features later operations turn are still the stock, Ø%1 mm.</source>
        <translation>Los elementos exteriores que tornean operaciones posteriores siguen en bruto, Ø%1 mm.</translation>
    </message>
    <message>
        <source>The boring bar is taken as held rigidly in the turret: no stiffness of a bar clamp is known, so the bar&apos;s deflection is a lower bound.</source>
        <translation>La barra de mandrinar se toma como sujeta rígidamente en la torreta: no se conoce la rigidez de ningún soporte de barra, así que la flexión de la barra es un límite inferior.</translation>
    </message>
    <message>
        <source>The bores later operations cut are still solid material (no pre-drilled hole is assumed).</source>
        <translation>Los agujeros que mecanizan las operaciones posteriores siguen siendo material macizo (no se supone ningún agujero pretaladrado).</translation>
    </message>
    <message>
        <source>Collet: no published stiffness of a collet or of the spindle holding one was found, so it is taken as rigid at the collet&apos;s face, which is optimistic. The verdicts give the stiffness each tolerance needs of it.</source>
        <translation>Pinza: no se encontró ninguna rigidez publicada de una pinza ni del husillo que la sujeta, así que se toma como rígida en la cara de la pinza, lo que es optimista. Los veredictos dan la rigidez que cada tolerancia necesita de ella.</translation>
    </message>
    <message>
        <source>Workpiece beam without the corrections for the root in the jaws and the shoulders: plain Timoshenko theory, up to about 10 % stiffer than a solid model where a chuck holds the part (docs/solid-fe.md).</source>
        <translation>Viga de la pieza sin las correcciones del empotramiento en las garras y de los resaltes: teoría de Timoshenko sin más, hasta un 10 % más rígida que un modelo sólido donde un plato sujeta la pieza (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Workpiece beam corrected from solid FE: built in %1 of its diameter inside the jaws, a hinge at each shoulder (docs/solid-fe.md).</source>
        <translation>Viga de la pieza corregida con EF sólidos: empotrada %1 veces su diámetro dentro de las garras, una articulación en cada resalte (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Workpiece beam corrected from solid FE: a hinge at each shoulder (docs/solid-fe.md).</source>
        <translation>Viga de la pieza corregida con EF sólidos: una articulación en cada resalte (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>Boring bar overhang not given: taken as the bore&apos;s depth and the program&apos;s clearance off the end face, %1 mm, the least that reaches; a longer overhang bends more.</source>
        <translation>Voladizo de la barra de mandrinar no indicado: se toma la profundidad del agujero más la distancia del programa a la cara frontal, %1 mm, lo mínimo que alcanza; un voladizo mayor flecta más.</translation>
    </message>
    <message>
        <source>Ambient temperature not given (environment): taken as the characterisation&apos;s reference, %1 °C, so no drift from it.</source>
        <translation>Temperatura ambiente no indicada (environment): se toma la de referencia de la caracterización, %1 °C, sin deriva por ella.</translation>
    </message>
    <message>
        <source>there is no pass %1 (the project has %2)</source>
        <translation>no hay pasada %1 (el proyecto tiene %2)</translation>
    </message>
    <message>
        <source>Time since the machine started not given (environment): taken as warmed through, %1 min (ten time constants), the largest drift of the size (not always of the form).</source>
        <translation>Tiempo desde el arranque de la máquina no indicado (environment): se toma como caliente del todo, %1 min (diez constantes de tiempo), la mayor deriva de la cota (no siempre de la forma).</translation>
    </message>
    <message>
        <source>Spindle–chuck tangential springs not measured: the chuck is taken as rigid tangentially (the radial springs are measured). A tangential deflection δ_t changes the machined radius by about δ_t²/2r only; give tangential_um in the test-bar fit to measure them.</source>
        <translation>Muelles tangenciales husillo–plato no medidos: el plato se toma como rígido tangencialmente (los muelles radiales están medidos). Una deformación tangencial δ_t cambia el radio mecanizado solo en unos δ_t²/2r; indique tangential_um en el ajuste de la barra de prueba para medirlos.</translation>
    </message>
</context>
<context>
    <name>DriveReadings</name>
    <message>
        <source>%1 is not a finite number (a current from three phases is not, when a phase is negative or not finite)</source>
        <translation>%1 no es un número finito (una corriente obtenida de tres fases no lo es cuando una fase es negativa o no finita)</translation>
    </message>
    <message>
        <source>%1 = %2 is negative</source>
        <translation>%1 = %2 es negativo</translation>
    </message>
    <message>
        <source>the spindle speed ω_s = %1 rad/s is not above zero: no cut</source>
        <translation>la velocidad del husillo ω_s = %1 rad/s no es mayor que cero: no hay corte</translation>
    </message>
    <message>
        <source>the spindle current I_s = %1 A is below its idle current I_s0 = %2 A plus friction current ΔI_sf = %3 A, so the cutting current ΔI_s (eq. 10) would be negative: measure the idle and friction currents again at this speed</source>
        <translation>la corriente del motor del husillo I_s = %1 A es inferior a su corriente en vacío I_s0 = %2 A más la corriente de fricción ΔI_sf = %3 A, por lo que la corriente de corte ΔI_s (ec. 10) sería negativa: vuelva a medir las corrientes en vacío y de fricción a esta velocidad</translation>
    </message>
    <message>
        <source>the feed current I_a = %1 A is below its idle current I_a0 = %2 A, so the cutting current ΔI_a would be negative: measure the idle current again at this feed speed</source>
        <translation>la corriente del motor de avance I_a = %1 A es inferior a su corriente en vacío I_a0 = %2 A, por lo que la corriente de corte ΔI_a sería negativa: vuelva a medir la corriente en vacío a esta velocidad de avance</translation>
    </message>
    <message>
        <source>the drive reading lacks the number &quot;%1&quot;</source>
        <translation>a la lectura de los accionamientos le falta el número «%1»</translation>
    </message>
</context>
<context>
    <name>ExternalTools</name>
    <message>
        <source>&quot;%1&quot; is not on the PATH</source>
        <translation>«%1» no está en el PATH</translation>
    </message>
    <message>
        <source>%1 is set to &quot;%2&quot;, which is not an executable file</source>
        <translation>%1 tiene el valor «%2», que no es un archivo ejecutable</translation>
    </message>
    <message>
        <source>%1 was not found: %2. Install it with: sudo apt install %3 (or run tools/bootstrap.sh), or set %4 to its executable.</source>
        <translation>No se ha encontrado %1: %2. Instálelo con: sudo apt install %3 (o ejecute tools/bootstrap.sh), o asigne a %4 la ruta de su ejecutable.</translation>
    </message>
</context>
<context>
    <name>FeedScheduleText</name>
    <message>
        <source>top of the feed range</source>
        <translation>extremo superior del rango de avance</translation>
    </message>
    <message>
        <source>the plan has no finishing pass</source>
        <translation>el plan no tiene pasada de acabado</translation>
    </message>
    <message>
        <source>Feeds from %1 to %2 mm/rev in steps of %3 mm/rev (the plan&apos;s feed range), each feature&apos;s the largest that holds its tolerances and the finishing pass&apos;s limits; the bores keep the programmed feed.</source>
        <translation>Avances de %1 a %2 mm/rev en pasos de %3 mm/rev (el rango de avance de la planificación), para cada elemento el mayor que mantiene sus tolerancias y los límites de la pasada de acabado; los taladros conservan el avance programado.</translation>
    </message>
</context>
<context>
    <name>FinishedExtent</name>
    <message>
        <source>%1 at z = %2 mm from r %3 to %4 mm</source>
        <translation>%1 en z = %2 mm de r %3 a %4 mm</translation>
    </message>
    <message>
        <source>z %1–%2 mm of %3</source>
        <translation>z %1–%2 mm de %3</translation>
    </message>
    <message>
        <source>not finished by this set-up&apos;s program, which leaves %1 as it was (see the program&apos;s warnings); on what it turns: %2</source>
        <translation>no terminado por el programa de esta sujeción, que deja %1 sin mecanizar (vea los avisos del programa); en lo que tornea: %2</translation>
    </message>
</context>
<context>
    <name>GCode</name>
    <message>
        <source>No compensation: toleranced diameters at the middle of their zone</source>
        <translation>Sin compensación: diámetros tolerados en el centro de su zona</translation>
    </message>
    <message>
        <source>%1 offset %2 um on diameter</source>
        <translation>%1 corrección de %2 um en el diámetro</translation>
    </message>
    <message>
        <source>%1 profile corrected by the predicted deviation</source>
        <translation>%1 perfil corregido con la desviación prevista</translation>
    </message>
    <message>
        <source>Compensated path: no feature needs a correction</source>
        <translation>Trayectoria compensada: ningún elemento necesita corrección</translation>
    </message>
    <message>
        <source>Compensated: %1</source>
        <translation>Compensada: %1</translation>
    </message>
    <message>
        <source>vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>vc %1 m/min, f %2 mm/rev, ap %3 mm</translation>
    </message>
    <message>
        <source>pass %1</source>
        <translation>pasada %1</translation>
    </message>
    <message>
        <source>passes %1-%2</source>
        <translation>pasadas %1-%2</translation>
    </message>
    <message>
        <source>%1 roughing %2</source>
        <translation>%1 desbaste %2</translation>
    </message>
    <message>
        <source>pass %1 finishing %2</source>
        <translation>pasada %1 acabado %2</translation>
    </message>
    <message>
        <source>%1, as chosen</source>
        <translation>%1, según la elección</translation>
    </message>
    <message>
        <source>%1, the control of machine %2</source>
        <translation>%1, el control de la máquina %2</translation>
    </message>
    <message>
        <source>%1: machine %2 has no CNC control in the data; choose the dialect of yours</source>
        <translation>%1: la máquina %2 no tiene control CNC en los datos; elija el dialecto del suyo</translation>
    </message>
    <message>
        <source>TolTurn %1: %2</source>
        <translation>TolTurn %1: %2</translation>
    </message>
    <message>
        <source>Material %1, insert %2, holder %3, clamping %4</source>
        <translation>Material %1, plaquita %2, portaherramientas %3, sujeción %4</translation>
    </message>
    <message>
        <source>Dialect: %1</source>
        <translation>Dialecto: %1</translation>
    </message>
    <message>
        <source>Conditions: %1</source>
        <translation>Condiciones: %1</translation>
    </message>
    <message>
        <source>%1, operation %2 of %3: the drawing&apos;s %4 end held; the right end face below is the free end of this set-up</source>
        <translation>%1, operación %2 de %3: extremo %4 del plano sujetado; la cara frontal derecha del programa siguiente es el extremo libre de este montaje</translation>
    </message>
    <message>
        <source>bore pass %1</source>
        <translation>pasada de mandrinado %1</translation>
    </message>
    <message>
        <source>bore passes %1-%2</source>
        <translation>pasadas de mandrinado %1-%2</translation>
    </message>
    <message>
        <source>bore pass %1 finishing %2</source>
        <translation>pasada de mandrinado %1 acabado %2</translation>
    </message>
    <message>
        <source>boring, roughing</source>
        <translation>mandrinado, desbaste</translation>
    </message>
    <message>
        <source>boring, finishing</source>
        <translation>mandrinado, acabado</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>desbaste</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>acabado</translation>
    </message>
    <message>
        <source>The bores are not in this program: the set-up has no boring bar (Set-up dock, Boring bar).</source>
        <translation>Los agujeros no están en este programa: la preparación no tiene barra de mandrinar (panel Preparación, Barra de mandrinar).</translation>
    </message>
    <message>
        <source>Tool %1: boring bar %2 (D%3 mm, overhang %4 mm), insert %5</source>
        <translation>Herramienta %1: barra de mandrinar %2 (D%3 mm, voladizo %4 mm), plaquita %5</translation>
    </message>
    <message>
        <source>The bores are not in this program: a centre holds the set-up&apos;s free end, so the boring bar cannot enter it. Bore them in a set-up held in the chuck alone.</source>
        <translation>Los agujeros no están en este programa: un punto sujeta el extremo libre de la preparación y la barra de mandrinar no puede entrar. Mandrínelos en una preparación sujeta solo en el plato.</translation>
    </message>
    <message>
        <source>Finishing feed scheduled by feature (TolTurn feed schedule): %1</source>
        <translation>Avance de acabado por elemento (programa de avances de TolTurn): %1</translation>
    </message>
    <message>
        <source>Roughing feed raised where a level cuts less than its depth, to the planned force (TolTurn feed schedule)</source>
        <translation>Avance de desbaste aumentado donde un nivel corta menos que su profundidad, hasta la fuerza planificada (programa de avances de TolTurn)</translation>
    </message>
    <message>
        <source>Roughing feed not scheduled: the plan&apos;s settings give no feed range to stay within.</source>
        <translation>Avance de desbaste no programado: los datos de planificación no dan un rango de avance que respetar.</translation>
    </message>
    <message>
        <source>The project has no finishing pass: its last pass (%1) is cut along the contour as the finishing pass, and the passes before it leave it its depth. Add a finishing pass.</source>
        <translation>El proyecto no tiene pasada de acabado: su última pasada (%1) se corta a lo largo del contorno como pasada de acabado, y las pasadas anteriores le dejan su profundidad. Añada una pasada de acabado.</translation>
    </message>
</context>
<context>
    <name>GCodeCommand</name>
    <message>
        <source>The turning program: the planned roughing passes and the finishing pass of the outer contour, nominal or compensated only where a tolerance needs it, for the machine&apos;s control (Fanuc/Haas, Sinumerik or LinuxCNC).</source>
        <translation>El programa de torneado: las pasadas de desbaste planificadas y la pasada de acabado del contorno exterior, nominal o compensado solo donde una tolerancia lo requiere, para el control de la máquina (Fanuc/Haas, Sinumerik o LinuxCNC).</translation>
    </message>
    <message>
        <source>File to write; - for standard output.</source>
        <translation>Archivo a escribir; - para la salida estándar.</translation>
    </message>
    <message>
        <source>Correct the path where a tolerance needs it (offset or profile).</source>
        <translation>Corregir la trayectoria donde una tolerancia lo requiere (corrección o perfil).</translation>
    </message>
    <message>
        <source>Control dialect: fanuc (also Haas), sinumerik or linuxcnc. Default: the machine&apos;s control.</source>
        <translation>Dialecto del control: fanuc (también Haas), sinumerik o linuxcnc. Por defecto: el control de la máquina.</translation>
    </message>
    <message>
        <source>Nose radius: &apos;control&apos; programs the contour with G42, the bore with G41 (the control compensates), &apos;tip-path&apos; the path of the imaginary tool tip computed by TolTurn. Default: control.</source>
        <translation>Radio de punta: &apos;control&apos; programa el contorno con G42, el agujero con G41 (compensa el control), &apos;tip-path&apos; la trayectoria de la punta teórica calculada por TolTurn. Por defecto: control.</translation>
    </message>
    <message>
        <source>Project file.</source>
        <translation>Archivo de proyecto.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE</source>
        <translation>indique un archivo de proyecto y -o ARCHIVO</translation>
    </message>
    <message>
        <source>--dialect: &apos;%1&apos; is not fanuc, sinumerik or linuxcnc</source>
        <translation>--dialect: &apos;%1&apos; no es fanuc, sinumerik ni linuxcnc</translation>
    </message>
    <message>
        <source>--nose: &apos;%1&apos; is not control or tip-path</source>
        <translation>--nose: &apos;%1&apos; no es control ni tip-path</translation>
    </message>
    <message>
        <source>dialect %1</source>
        <translation>dialecto %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>aviso: %1</translation>
    </message>
    <message>
        <source>Compensate with what was learned of the machine from its measured parts (learn --save).</source>
        <translation>Compensar con lo aprendido de la máquina a partir de sus piezas medidas (learn --save).</translation>
    </message>
    <message>
        <source>feed schedule: %1 kept at the programmed %2 mm/rev: %3 is not held at any feed of the range (a case for compensation)</source>
        <translation>programa de avances: %1 se mantiene en el avance programado de %2 mm/rev: %3 no se cumple con ningún avance del rango (un caso para la compensación)</translation>
    </message>
    <message>
        <source>feed schedule: %1 at %2 mm/rev (programmed %3), limited by %4</source>
        <translation>programa de avances: %1 a %2 mm/rev (programado %3), limitado por %4</translation>
    </message>
    <message>
        <source>feed schedule: finishing pass %1 s at the programmed feed, %2 s scheduled (%3 %)</source>
        <translation>programa de avances: pasada de acabado %1 s con el avance programado, %2 s según el programa (%3 %)</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>nota: %1</translation>
    </message>
    <message>
        <source>feed schedule: roughing passes %1 s at the programmed feed, %2 s scheduled (%3 %)</source>
        <translation>programa de avances: pasadas de desbaste %1 s con el avance programado, %2 s según el programa (%3 %)</translation>
    </message>
    <message>
        <source>Cut each feature of the finishing pass at its own feed: the largest in the plan&apos;s feed range that holds its tolerances and the pass&apos;s limits. With --compensated, the features no feed holds keep the programmed feed and are compensated at it.</source>
        <translation>Mecanizar cada elemento de la pasada de acabado con su propio avance: el mayor del rango de avances del plan que cumple sus tolerancias y los límites de la pasada. Con --compensated, los elementos que ningún avance cumple conservan el avance programado y se compensan con él.</translation>
    </message>
    <message>
        <source>compensation: %1 %2, residual %3 → %4 µm</source>
        <translation>compensación: %1 %2, residuo %3 → %4 µm</translation>
    </message>
    <message>
        <source>compensation: no tolerance needs a correction; the moves are the nominal program&apos;s</source>
        <translation>compensación: ninguna tolerancia necesita corrección; los movimientos son los del programa nominal</translation>
    </message>
    <message>
        <source>program %1, checksum %2 (SHA-256, first 16 digits)</source>
        <translation>programa %1, suma de control %2 (SHA-256, primeros 16 dígitos)</translation>
    </message>
</context>
<context>
    <name>HybridRbf</name>
    <message>
        <source>%1 input rows but %2 targets</source>
        <translation>%1 filas de entrada pero %2 objetivos</translation>
    </message>
    <message>
        <source>%1 samples; the network needs at least 3</source>
        <translation>%1 muestras; la red necesita al menos 3</translation>
    </message>
    <message>
        <source>an input or a target is not a finite number</source>
        <translation>una entrada o un objetivo no es un número finito</translation>
    </message>
    <message>
        <source>no network could be fitted to the samples</source>
        <translation>no se pudo ajustar ninguna red a las muestras</translation>
    </message>
</context>
<context>
    <name>ImportCommand</name>
    <message>
        <source>--%1 takes a number from 0, not &apos;%2&apos;</source>
        <translation>--%1 admite un número a partir de 0, no &apos;%2&apos;</translation>
    </message>
    <message>
        <source>no project written: the import has errors</source>
        <translation>no se ha escrito ningún proyecto: la importación tiene errores</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Escribir el resultado en formato JSON.</translation>
    </message>
    <message>
        <source>Turn the part end for end (z = 0 at the other end).</source>
        <translation>Dar la vuelta a la pieza (z = 0 en el otro extremo).</translation>
    </message>
    <message>
        <source>The body to import, from 0 (default: the largest).</source>
        <translation>Cuerpo que se va a importar, a partir de 0 (por defecto: el mayor).</translation>
    </message>
    <message>
        <source>The axis to turn about, from 0 (default: most revolved area).</source>
        <translation>Eje alrededor del cual se tornea, a partir de 0 (por defecto: el de mayor área de revolución).</translation>
    </message>
    <message>
        <source>The work material&apos;s id (default: %1).</source>
        <translation>Id del material de la pieza (por defecto: %1).</translation>
    </message>
    <message>
        <source>The machine&apos;s id (default: %1).</source>
        <translation>Id de la máquina (por defecto: %1).</translation>
    </message>
    <message>
        <source>The STEP or IGES file.</source>
        <translation>Archivo STEP o IGES.</translation>
    </message>
    <message>
        <source>give one STEP or IGES file and -o PROJECT</source>
        <translation>indique un archivo STEP o IGES y -o PROYECTO</translation>
    </message>
    <message>
        <source>Write the project&apos;s part as a solid of revolution to a STEP file in mm (AP214), for CAD and CAM.</source>
        <translation>Escribir la pieza del proyecto como cuerpo de revolución en un archivo STEP en mm (AP214), para CAD y CAM.</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>Archivo de proyecto.</translation>
    </message>
    <message>
        <source>give one project file and -o FILE.step</source>
        <translation>indique un archivo de proyecto y -o ARCHIVO.step</translation>
    </message>
    <message>
        <source>%1: written</source>
        <translation>%1: escrito</translation>
    </message>
    <message>
        <source>cannot read back &apos;%1&apos;: %2</source>
        <translation>no se puede releer &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>The project file to write (&apos;-&apos;: standard output).</source>
        <translation>El archivo de proyecto que escribir (&apos;-&apos;: salida estándar).</translation>
    </message>
    <message>
        <source>--json and -o - would both write to standard output</source>
        <translation>--json y -o - escribirían ambos en la salida estándar</translation>
    </message>
    <message>
        <source>The STEP file to write (&apos;-&apos;: standard output).</source>
        <translation>El archivo STEP que escribir (&apos;-&apos;: salida estándar).</translation>
    </message>
    <message>
        <source>%1: written, part &quot;%2&quot;, %3 mm long, %4 outer and %5 inner features, %6</source>
        <translation>%1: escrito, pieza «%2», %3 mm de largo, %4 elementos exteriores y %5 interiores, %6</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
        </translation>
    </message>
    <message>
        <source>Report the progress on standard error, as lines &quot;progress F&quot; with F from 0 to 1.</source>
        <translation>Informar del progreso en la salida de error estándar, como líneas «progress F» con F de 0 a 1.</translation>
    </message>
    <message>
        <source>Turn a STEP (.step, .stp) or IGES (.iges, .igs) part into a new project: the outer and inner contour in mm, z = 0 at the left end; flats and keyways become milled features, other features that are not turned (cross holes) are listed as warnings.</source>
        <translation>Convertir una pieza STEP (.step, .stp) o IGES (.iges, .igs) en un proyecto nuevo: el contorno exterior e interior en mm, z = 0 en el extremo izquierdo; las caras planas y los chaveteros se convierten en elementos fresados, y los demás elementos que no se tornean (agujeros transversales) se listan como avisos.</translation>
    </message>
    <message>
        <source>a choice is three whole numbers &quot;SOLID AXIS FLIP&quot; (SOLID and AXIS from 0, -1 for the default; FLIP 0 or 1), not &apos;%1&apos;</source>
        <translation>una elección son tres números enteros &quot;SOLID AXIS FLIP&quot; (SOLID y AXIS desde 0, -1 para el valor por defecto; FLIP 0 o 1), no &apos;%1&apos;</translation>
    </message>
    <message>
        <source>With --json: read the file once, print each result as one line, then extract again for each line &quot;SOLID AXIS FLIP&quot; on standard input, until it ends.</source>
        <translation>Con --json: leer el archivo una vez, escribir cada resultado en una línea y extraer de nuevo para cada línea &quot;SOLID AXIS FLIP&quot; de la entrada estándar, hasta que termine.</translation>
    </message>
    <message>
        <source>--choose needs --json and a project file (-o PROJECT)</source>
        <translation>--choose necesita --json y un archivo de proyecto (-o PROJECT)</translation>
    </message>
    <message>
        <source>--material: unknown material &quot;%1&quot;; the materials are: %2</source>
        <translation>--material: material desconocido «%1»; los materiales son: %2</translation>
    </message>
    <message>
        <source>--machine: unknown machine &quot;%1&quot;; the machines are: %2</source>
        <translation>--machine: máquina desconocida «%1»; las máquinas son: %2</translation>
    </message>
</context>
<context>
    <name>InputBounds</name>
    <message>
        <source>%1 is beyond what TolTurn computes with: at most %2%3</source>
        <translation>%1 supera lo que TolTurn calcula: como mucho %2%3</translation>
    </message>
    <message>
        <source>holds %1 entries, more than the %2 TolTurn computes with</source>
        <translation>contiene %1 entradas, más que las %2 con las que calcula TolTurn</translation>
    </message>
</context>
<context>
    <name>InsertCodes</name>
    <message>
        <source>insert code &quot;%1&quot;: %2</source>
        <translation>código de plaquita &quot;%1&quot;: %2</translation>
    </message>
    <message>
        <source>not an ISO 1832 designation (four letters, then size, thickness and corner digits, as in CNMG 120408)</source>
        <translation>no es una designación ISO 1832 (cuatro letras y después las cifras de tamaño, espesor y radio de punta, como en CNMG 120408)</translation>
    </message>
    <message>
        <source>position 1 (shape) &apos;%1&apos; is not one of %2</source>
        <translation>posición 1 (forma): &apos;%1&apos; no es ninguno de %2</translation>
    </message>
    <message>
        <source>position 2 (clearance angle) &apos;%1&apos; is not one of %2</source>
        <translation>posición 2 (ángulo de incidencia): &apos;%1&apos; no es ninguno de %2</translation>
    </message>
    <message>
        <source>position 3 (tolerance class) &apos;%1&apos; is not one of %2</source>
        <translation>posición 3 (clase de tolerancia): &apos;%1&apos; no es ninguno de %2</translation>
    </message>
    <message>
        <source>position 4 (type) &apos;%1&apos; is not one of %2</source>
        <translation>posición 4 (tipo): &apos;%1&apos; no es ninguno de %2</translation>
    </message>
    <message>
        <source>position 5 (size) &apos;%1&apos; is not a standard cutting-edge length for shape %2</source>
        <translation>posición 5 (tamaño): &apos;%1&apos; no es una longitud de filo normalizada para la forma %2</translation>
    </message>
    <message>
        <source>position 6 (thickness) &apos;%1&apos; is not an ISO 1832 thickness symbol</source>
        <translation>posición 6 (espesor): &apos;%1&apos; no es un símbolo de espesor ISO 1832</translation>
    </message>
    <message>
        <source>position 7 of a round insert is M0 or 00, not &apos;%1&apos;</source>
        <translation>la posición 7 de una plaquita redonda es M0 o 00, no &apos;%1&apos;</translation>
    </message>
    <message>
        <source>position 7 (corner radius) &apos;%1&apos; gives a sharp corner, which turning inserts of shape %2 do not have in TolTurn&apos;s models</source>
        <translation>posición 7 (radio de punta): &apos;%1&apos; indica una punta viva, que las plaquitas de torneado de forma %2 no tienen en los modelos de TolTurn</translation>
    </message>
</context>
<context>
    <name>Iso286</name>
    <message>
        <source>hole</source>
        <translation>agujero</translation>
    </message>
    <message>
        <source>shaft</source>
        <translation>eje</translation>
    </message>
    <message>
        <source>the nominal size is not a finite number</source>
        <translation>la medida nominal no es un número finito</translation>
    </message>
    <message>
        <source>0 mm is not a nominal size: the first range of ISO 286 is above 0 up to and including 3 mm</source>
        <translation>0 mm no es una medida nominal: el primer grupo de ISO 286 va de más de 0 hasta 3 mm inclusive</translation>
    </message>
    <message>
        <source>the nominal size must be above 0 mm, but is %1 mm</source>
        <translation>la medida nominal debe ser mayor que 0 mm, pero es %1 mm</translation>
    </message>
    <message>
        <source>%1 mm is above 3150 mm, the largest nominal size of ISO 286</source>
        <translation>%1 mm supera los 3150 mm, la mayor medida nominal de ISO 286</translation>
    </message>
    <message>
        <source>%1 is given by ISO 286-1 only for nominal sizes up to and including 500 mm, not for %2 mm</source>
        <translation>ISO 286-1 solo define %1 para medidas nominales hasta 500 mm inclusive, no para %2 mm</translation>
    </message>
    <message>
        <source>%1 shall not be used for nominal sizes up to and including 1 mm (ISO 286-1 Table 1), but the size is %2 mm</source>
        <translation>%1 no debe utilizarse para medidas nominales hasta 1 mm inclusive (ISO 286-1, tabla 1), pero la medida es %2 mm</translation>
    </message>
    <message>
        <source>%1 above 500 mm is given by ISO 286-1 for experimental use only (size %2 mm)</source>
        <translation>ISO 286-1 define %1 por encima de 500 mm solo para uso experimental (medida %2 mm)</translation>
    </message>
    <message>
        <source>hole %1 is not defined: ISO 286-1 forms %2 up to IT%3 as ES = -ei + Δ, and tabulates Δ only for IT3 to IT8</source>
        <translation>el agujero %1 no está definido: ISO 286-1 forma %2 hasta IT%3 como ES = -ei + Δ y solo tabula Δ de IT3 a IT8</translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 gives K above IT8 only for nominal sizes up to and including 3 mm</source>
        <translation>el agujero %1 no está definido para una medida nominal de %2 mm: ISO 286-1 solo define K por encima de IT8 para medidas nominales hasta 3 mm inclusive</translation>
    </message>
    <message>
        <source>hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 says N above IT8 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation>el agujero %1 no está definido para una medida nominal de %2 mm: según ISO 286-1, N por encima de IT8 no debe utilizarse para medidas nominales hasta 1 mm inclusive</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 says the fundamental deviations %4 shall not be used for nominal sizes up to and including 1 mm</source>
        <translation>el %1 %2 no está definido para una medida nominal de %3 mm: según ISO 286-1, las diferencias fundamentales %4 no deben utilizarse para medidas nominales hasta 1 mm inclusive</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives the fundamental deviation %4 only above %5 mm up to and including %6 mm</source>
        <translation>el %1 %2 no está definido para una medida nominal de %3 mm: ISO 286-1 solo define la diferencia fundamental %4 por encima de %5 mm y hasta %6 mm inclusive</translation>
    </message>
    <message>
        <source>%1 %2 is not defined: ISO 286-1 tabulates %3 only for the grades IT%4 to IT%5 (the symmetric %6 covers every grade)</source>
        <translation>el %1 %2 no está definido: ISO 286-1 solo tabula %3 para los grados IT%4 a IT%5 (la diferencia simétrica %6 abarca todos los grados)</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives %4 only up to and including 500 mm</source>
        <translation>el %1 %2 no está definido para una medida nominal de %3 mm: ISO 286-1 solo define %4 hasta 500 mm inclusive</translation>
    </message>
    <message>
        <source>%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives j8 only up to and including 3 mm</source>
        <translation>el %1 %2 no está definido para una medida nominal de %3 mm: ISO 286-1 solo define j8 hasta 3 mm inclusive</translation>
    </message>
    <message>
        <source>the tolerance class is empty; write a fundamental deviation letter and a tolerance grade, such as H7 or g6</source>
        <translation>la clase de tolerancia está vacía; escriba una letra de diferencia fundamental y un grado de tolerancia, como H7 o g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tolerance class: write a fundamental deviation letter and a tolerance grade, such as H7, g6 or js6</source>
        <translation>&quot;%1&quot; no es una clase de tolerancia: escriba una letra de diferencia fundamental y un grado de tolerancia, como H7, g6 o js6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; mixes upper and lower case in &quot;%2&quot;: hole letters are upper case (H7), shaft letters lower case (g6)</source>
        <translation>&quot;%1&quot; mezcla mayúsculas y minúsculas en &quot;%2&quot;: las letras de agujero van en mayúsculas (H7) y las de eje en minúsculas (g6)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not a fundamental deviation of ISO 286-1; the %3 letters are %4</source>
        <translation>&quot;%1&quot;: &quot;%2&quot; no es una diferencia fundamental de ISO 286-1; las letras de %3 son %4</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: IT%2 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation>&quot;%1&quot;: IT%2 no es un grado de tolerancia normalizado; los grados son IT01, IT0 e IT1 a IT18</translation>
    </message>
    <message>
        <source>IT%1 is not a standard tolerance grade; the grades are IT01, IT0 and IT1 to IT18</source>
        <translation>IT%1 no es un grado de tolerancia normalizado; los grados son IT01, IT0 e IT1 a IT18</translation>
    </message>
    <message>
        <source>%1 is a shaft class; the first class of a fit is the hole, written in upper case (H7)</source>
        <translation>%1 es una clase de eje; la primera clase de un ajuste es la del agujero, escrita en mayúsculas (H7)</translation>
    </message>
    <message>
        <source>%1 is a hole class; the second class of a fit is the shaft, written in lower case (g6)</source>
        <translation>%1 es una clase de agujero; la segunda clase de un ajuste es la del eje, escrita en minúsculas (g6)</translation>
    </message>
    <message>
        <source>clearance</source>
        <translation>con juego</translation>
    </message>
    <message>
        <source>transition</source>
        <translation>indeterminado</translation>
    </message>
    <message>
        <source>interference</source>
        <translation>con apriete</translation>
    </message>
    <message>
        <source>the designation is empty; write one such as 50 H7, Ø50 g6 or 50 H7/g6</source>
        <translation>la designación está vacía; escriba una como 50 H7, Ø50 g6 o 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the diameter sign must be followed by the nominal size, as in Ø50 H7</source>
        <translation>&quot;%1&quot;: el símbolo de diámetro debe ir seguido de la medida nominal, como en Ø50 H7</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no tolerance class; write one after the nominal size, such as 50 H7 or 50 H7/g6</source>
        <translation>&quot;%1&quot; no tiene clase de tolerancia; escriba una después de la medida nominal, como 50 H7 o 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a designation: a fit is a hole class, a slash and a shaft class, as in 50 H7/g6</source>
        <translation>&quot;%1&quot; no es una designación: un ajuste es una clase de agujero, una barra y una clase de eje, como en 50 H7/g6</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: a fit is written hole class first (upper case), then the shaft class (lower case), as in 50 H7/g6</source>
        <translation>&quot;%1&quot;: un ajuste se escribe primero con la clase del agujero (mayúsculas) y después con la del eje (minúsculas), como en 50 H7/g6</translation>
    </message>
    <message>
        <source>the designation &quot;%1&quot; names %2 mm, but %3 mm was given separately</source>
        <translation>la designación &quot;%1&quot; indica %2 mm, pero se ha indicado %3 mm por separado</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no nominal size; write it in the designation (50 H7) or give it separately</source>
        <translation>&quot;%1&quot; no tiene medida nominal; escríbala en la designación (50 H7) o indíquela por separado</translation>
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
        <translation>el número %1</translation>
    </message>
    <message>
        <source>the text &quot;%1&quot;</source>
        <translation>el texto &quot;%1&quot;</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>una lista</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>un objeto</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nada</translation>
    </message>
    <message>
        <source>this field is required but missing</source>
        <translation>este campo es obligatorio, pero falta</translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation>se esperaba %1 y se ha encontrado %2</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>un número</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>un número entero</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>un texto</translation>
    </message>
    <message>
        <source>unknown %1 &quot;%2&quot;; expected one of: %3</source>
        <translation>%1 desconocido &quot;%2&quot;; se esperaba uno de: %3</translation>
    </message>
    <message>
        <source>unknown field, kept as it is</source>
        <translation>campo desconocido, se conserva tal cual</translation>
    </message>
</context>
<context>
    <name>LearnCommand</name>
    <message>
        <source>The machine to learn.</source>
        <translation>La máquina a aprender.</translation>
    </message>
    <message>
        <source>The store: an SQLite file, or postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).</source>
        <translation>El almacén: un archivo SQLite o postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (por defecto: %1).</translation>
    </message>
    <message>
        <source>gcv (default) or bic: when the network stops growing.</source>
        <translation>gcv (por defecto) o bic: cuándo deja de crecer la red.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Imprimir el resultado como JSON.</translation>
    </message>
    <message>
        <source>give --machine ID, and --criterion gcv or bic</source>
        <translation>indique --machine ID, y --criterion gcv o bic</translation>
    </message>
    <message>
        <source>%1: %2 parts, %3 measured points</source>
        <translation>%1: %2 piezas, %3 puntos medidos</translation>
    </message>
    <message>
        <source>  geometric error: %1 µm per mm of diameter, %2 µm per mm along z (taper), %3 µm offset</source>
        <translation>  error geométrico: %1 µm por mm de diámetro, %2 µm por mm a lo largo de z (conicidad), %3 µm de desplazamiento</translation>
    </message>
    <message>
        <source>  network: %1 of %2 nodes kept (radius scale %3), leave-one-out RMS %4 µm</source>
        <translation>  red: %1 de %2 nodos conservados (escala de radio %3), RMS leave-one-out %4 µm</translation>
    </message>
    <message>
        <source>  parts predicted without having been learned from (leave one part out): physics alone %1 µm RMS, physics + learned %2 µm RMS</source>
        <translation>  piezas predichas sin haber aprendido de ellas (dejando una fuera): solo física %1 µm RMS, física + aprendido %2 µm RMS</translation>
    </message>
    <message>
        <source>Keep what was learned in the store as the machine&apos;s model, for the commands&apos; --learned.</source>
        <translation>Guardar lo aprendido en el almacén como modelo de la máquina, para --learned de las órdenes.</translation>
    </message>
    <message>
        <source>kept as the model of %1 (number %2) in %3</source>
        <translation>guardado como modelo de %1 (número %2) en %3</translation>
    </message>
    <message>
        <source>nothing has been learned of %1 yet: run &apos;learn --machine %1 --save&apos;</source>
        <translation>aún no se ha aprendido nada de %1: ejecute «learn --machine %1 --save»</translation>
    </message>
    <message>
        <source>%1 has %2</source>
        <translation>%1 tiene %2</translation>
    </message>
    <message>
        <source>forces from motor currents: %1 calibration cuts; leaving one out, F_t to %2 N RMS, F_a to %3 N RMS</source>
        <translation>fuerzas a partir de corrientes de motor: %1 cortes de calibración; dejando uno fuera, F_t con %2 N RMS, F_a con %3 N RMS</translation>
    </message>
    <message>
        <source>Cuts with motor currents and dynamometer forces (CSV): parts that carry their drives&apos; readings then learn from forces estimated from their motor currents (Li &amp; Du eq. 7–19).</source>
        <translation>Cortes con corrientes de motor y fuerzas de dinamómetro (CSV): las piezas que llevan las lecturas de sus accionamientos aprenden entonces de fuerzas estimadas a partir de sus corrientes de motor (Li &amp; Du ec. 7–19).</translation>
    </message>
    <message>
        <source>%1 of %2 parts learned from forces estimated from their motor currents</source>
        <translation>%1 de %2 piezas aprendieron de fuerzas estimadas a partir de sus corrientes de motor</translation>
    </message>
    <message>
        <source>  learned at: %1</source>
        <translation>  aprendido con: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>aviso: %1</translation>
    </message>
</context>
<context>
    <name>LearnedModelJson</name>
    <message>
        <source>the learned model has no valid &quot;%1&quot;</source>
        <translation>el modelo aprendido no tiene un «%1» válido</translation>
    </message>
</context>
<context>
    <name>MachineLearning</name>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>%1, model %2, %3 parts</source>
        <translation>%1, modelo %2, %3 piezas</translation>
    </message>
    <message>
        <source>the model %1 of %2 is damaged: %3</source>
        <translation>el modelo %1 de %2 está dañado: %3</translation>
    </message>
    <message>
        <source>the project snapshot of part %1 does not read</source>
        <translation>la copia del proyecto de la pieza %1 no se puede leer</translation>
    </message>
    <message>
        <source>the physics model cannot compute the snapshot of part %1</source>
        <translation>el modelo físico no puede calcular la copia del proyecto de la pieza %1</translation>
    </message>
    <message>
        <source>as learned from its measured parts (%1, learned %2 UTC): parts not learned from were predicted to %3 µm RMS, the physics alone to %4 µm; its stiffness range is not used</source>
        <translation>según lo aprendido de sus piezas medidas (%1, aprendido %2 UTC): las piezas no usadas para aprender se predijeron con %3 µm RMS, la física sola con %4 µm; no se usa su rango de rigidez</translation>
    </message>
    <message>
        <source>%1 with %2: %3</source>
        <translation>%1 con %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>%n stored part(s)</source>
        <translation>
            <numerusform>%n pieza guardada</numerusform>
            <numerusform>%n piezas guardadas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n usable point(s)</source>
        <translation>
            <numerusform>%n punto utilizable</numerusform>
            <numerusform>%n puntos utilizables</numerusform>
        </translation>
    </message>
    <message>
        <source>part %1 is left out: its project was computed against another characterisation of the machine than the newest part %2, and a model learns what one physics misses</source>
        <translation>la pieza %1 queda fuera: su proyecto se calculó con otra caracterización de la máquina que la pieza más reciente %2, y un modelo aprende lo que falta a una sola física</translation>
    </message>
    <message>
        <source>%1 was learned against another characterisation of %2 than this project&apos;s (its springs, supports or thermal drift differ): what it learned is what that physics missed, not this one. Learn again from parts cut with this characterisation, or predict without it</source>
        <translation>%1 se aprendió con otra caracterización de %2 distinta de la de este proyecto (sus muelles, apoyos o deriva térmica difieren): lo que aprendió es lo que faltaba a aquella física, no a esta. Aprenda de nuevo con piezas cortadas con esta caracterización, o prediga sin él</translation>
    </message>
    <message>
        <source>part %1 is left out: it is part %2 stored again (the same project, time and points)</source>
        <translation>la pieza %1 queda fuera: es la pieza %2 guardada otra vez (el mismo proyecto, hora y puntos)</translation>
    </message>
    <message>
        <source>the measured points lie on one %1</source>
        <translation>los puntos medidos están en un solo valor de %1</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>diámetro</translation>
    </message>
    <message>
        <source>position z</source>
        <translation>posición z</translation>
    </message>
    <message>
        <source>the measured points&apos; diameters and positions z move together (correlation %1)</source>
        <translation>los diámetros y las posiciones z de los puntos medidos cambian juntos (correlación %1)</translation>
    </message>
    <message>
        <source>%1: the geometric error&apos;s split between diameter and z is not determined, and what was learned holds along the measured points only; measure features of other diameters at other z</source>
        <translation>%1: el reparto del error geométrico entre diámetro y z no está determinado, y lo aprendido vale solo a lo largo de los puntos medidos; mida elementos de otros diámetros en otras z</translation>
    </message>
    <message>
        <source>What was learned predicts parts it did not learn from worse than the physics alone (%1 against %2 µm RMS): it adds error here. Learn from more parts, or predict without it</source>
        <translation>Lo aprendido predice las piezas de las que no aprendió peor que la física sola (%1 frente a %2 µm RMS): aquí añade error. Aprenda de más piezas o prediga sin ello</translation>
    </message>
</context>
<context>
    <name>MeasuredParts</name>
    <message>
        <source>the part&apos;s profile has no feature &quot;%1&quot;</source>
        <translation>el perfil de la pieza no tiene el elemento «%1»</translation>
    </message>
    <message>
        <source>z = %1 mm is not on feature %2 (z from %3 to %4 mm)</source>
        <translation>z = %1 mm no está en el elemento %2 (z de %3 a %4 mm)</translation>
    </message>
    <message>
        <source>a diameter of %1 mm does not fit feature %2 (Ø%3 to Ø%4 mm)</source>
        <translation>un diámetro de %1 mm no corresponde al elemento %2 (Ø%3 a Ø%4 mm)</translation>
    </message>
    <message>
        <source>a radial deviation of %1 mm is beyond the ±%2 mm of a turned part</source>
        <translation>una desviación radial de %1 mm supera los ±%2 mm de una pieza torneada</translation>
    </message>
    <message>
        <source>the machine the part was cut on is not given</source>
        <translation>no se indica la máquina en que se mecanizó la pieza</translation>
    </message>
    <message>
        <source>the time of measurement is not given</source>
        <translation>no se indica el momento de la medición</translation>
    </message>
    <message>
        <source>the time since start must be from 0 to %1 min, not %2</source>
        <translation>el tiempo desde el arranque debe ir de 0 a %1 min, no %2</translation>
    </message>
    <message>
        <source>the ambient temperature must be from %1 to %2 °C, not %3</source>
        <translation>la temperatura ambiente debe ir de %1 a %2 °C, no %3</translation>
    </message>
    <message>
        <source>the project the part was cut from is not a valid project%1</source>
        <translation>el proyecto del que se mecanizó la pieza no es un proyecto válido%1</translation>
    </message>
    <message>
        <source>the part has no measured point</source>
        <translation>la pieza no tiene ningún punto medido</translation>
    </message>
    <message>
        <source>a CMM point needs finite x and y (x = %1, y = %2 mm)</source>
        <translation>un punto de MMC necesita x e y finitos (x = %1, y = %2 mm)</translation>
    </message>
    <message>
        <source>a CMM point at radius %1 mm is not on feature %2 (R%3 to R%4 mm)</source>
        <translation>un punto de MMC en el radio %1 mm no está en el elemento %2 (R%3 a R%4 mm)</translation>
    </message>
    <message>
        <source>the part was cut on %1, but its project is planned for %2: set the project&apos;s machine to %1 as it was cut, then store the part</source>
        <translation>la pieza se mecanizó en %1, pero su proyecto está planificado para %2: ponga %1 como máquina del proyecto, tal como se mecanizó, y guarde la pieza</translation>
    </message>
    <message>
        <source>a CMM point&apos;s radius %1 mm is not √(x² + y²) = %2 mm</source>
        <translation>el radio %1 mm de un punto de MMC no es √(x² + y²) = %2 mm</translation>
    </message>
</context>
<context>
    <name>MeasuredResiduals</name>
    <message>
        <source>part %1 is left out: its project snapshot does not read</source>
        <translation>la pieza %1 queda fuera: su copia del proyecto no se puede leer</translation>
    </message>
    <message>
        <source>part %1 is left out: the physics model cannot compute its project</source>
        <translation>la pieza %1 queda fuera: el modelo físico no puede calcular su proyecto</translation>
    </message>
    <message>
        <source>%1 measured points; learning needs at least 3</source>
        <translation>%1 puntos medidos; el aprendizaje necesita al menos 3</translation>
    </message>
    <message>
        <source>%1 measured part(s); leaving one out needs at least 2</source>
        <translation>%1 pieza(s) medida(s); dejar una fuera necesita al menos 2</translation>
    </message>
    <message>
        <source>The predicted radius errors include what was learned from measured parts (%1): the machine&apos;s measured behaviour replaces its stiffness range.</source>
        <translation>Los errores de radio predichos incluyen lo aprendido de piezas medidas (%1): el comportamiento medido de la máquina sustituye a su rango de rigidez.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>pieza %1: %2</translation>
    </message>
    <message>
        <source>part %1: its forces are the physics model&apos;s, not estimated from its motor currents</source>
        <translation>pieza %1: sus fuerzas son las del modelo físico, no estimadas a partir de sus corrientes de motor</translation>
    </message>
    <message>
        <source>part %1: %2 of its %3 points are not compared with the physics (on a face or on a feature its set-up&apos;s passes do not turn)</source>
        <translation>pieza %1: %2 de sus %3 puntos no se comparan con la física (en una cara o en un elemento que las pasadas de su amarre no tornean)</translation>
    </message>
    <message>
        <source>part %1: its motor currents are of the first set-up&apos;s finishing cut; %2 points cut in a later set-up are compared at the force model&apos;s forces</source>
        <translation>pieza %1: sus corrientes de motor son del corte de acabado de la primera sujeción; %2 puntos cortados en una sujeción posterior se comparan con las fuerzas del modelo de fuerzas</translation>
    </message>
    <message>
        <source>%1 %2 (measured parts %3)</source>
        <translation>%1 %2 (piezas medidas %3)</translation>
    </message>
    <message>
        <source>spindle speed [rpm]</source>
        <translation>velocidad del husillo [rpm]</translation>
    </message>
    <message>
        <source>feed [mm/rev]</source>
        <translation>avance [mm/rev]</translation>
    </message>
    <message>
        <source>with part %1 left out: %2</source>
        <translation>sin la pieza %1: %2</translation>
    </message>
    <message>
        <source>This plan is cut at other conditions than the parts the learned model was measured on: %1. There what was learned is extrapolated (a condition the parts did not vary is taken to have no effect, and the network&apos;s correction fades away from the conditions it learned at); measure parts cut at these conditions</source>
        <translation>Este plan se corta en otras condiciones que las piezas con las que se midió el modelo aprendido: %1. Allí lo aprendido se extrapola (una condición que las piezas no variaron se considera sin efecto, y la corrección de la red se desvanece lejos de las condiciones aprendidas); mida piezas cortadas en estas condiciones</translation>
    </message>
    <message>
        <source>spindle speed %1 rpm, feed %2 mm/rev, passive force %3 N, %4 min since start, ambient %5 °C, diameter %6 mm, z %7 mm</source>
        <translation>velocidad del husillo %1 rpm, avance %2 mm/rev, fuerza pasiva %3 N, %4 min desde el arranque, ambiente %5 °C, diámetro %6 mm, z %7 mm</translation>
    </message>
    <message>
        <source>passive force [N]</source>
        <translation>fuerza pasiva [N]</translation>
    </message>
    <message>
        <source>time since start [min]</source>
        <translation>tiempo desde el arranque [min]</translation>
    </message>
    <message>
        <source>ambient temperature [°C]</source>
        <translation>temperatura ambiente [°C]</translation>
    </message>
</context>
<context>
    <name>MeasurementCsv</name>
    <message>
        <source>a line needs one of diameter_mm, radial_deviation_um, or x_mm and y_mm (a CMM point)</source>
        <translation>una línea necesita diameter_mm, radial_deviation_um, o x_mm e y_mm (un punto de MMC)</translation>
    </message>
</context>
<context>
    <name>MeasurementFiles</name>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>no se puede abrir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>the header lacks the column &quot;%1&quot;; it needs %2</source>
        <translation>a la cabecera le falta la columna &quot;%1&quot;; necesita %2</translation>
    </message>
    <message>
        <source>%1 must be a number%2, not &quot;%3&quot;</source>
        <translation>%1 debe ser un número%2, no &quot;%3&quot;</translation>
    </message>
    <message>
        <source> above zero</source>
        <translation> mayor que cero</translation>
    </message>
    <message>
        <source>the file has no header line</source>
        <translation>el archivo no tiene línea de cabecera</translation>
    </message>
    <message>
        <source>the file has no measurement</source>
        <translation>el archivo no contiene ninguna medición</translation>
    </message>
    <message>
        <source>%1 must not be empty</source>
        <translation>%1 no debe estar vacío</translation>
    </message>
    <message>
        <source>%1 must be at most 1e9 in size, not &quot;%2&quot;</source>
        <translation>%1 debe ser como mucho 1e9 en valor absoluto, no «%2»</translation>
    </message>
    <message>
        <source>%1 must be a number with a decimal point, not &quot;%2&quot;</source>
        <translation>%1 debe ser un número con punto decimal, no «%2»</translation>
    </message>
    <message>
        <source>the line has %1 cells, the header %2: &quot;%3&quot;</source>
        <translation>la línea tiene %1 celdas, la cabecera %2: «%3»</translation>
    </message>
    <message>
        <source>the header names the column &quot;%1&quot; twice, as columns %2 and %3</source>
        <translation>la cabecera nombra la columna &quot;%1&quot; dos veces, como columnas %2 y %3</translation>
    </message>
</context>
<context>
    <name>MeasurementSchema</name>
    <message>
        <source>the store refused &quot;%1&quot;: %2</source>
        <translation>el almacén rechazó «%1»: %2</translation>
    </message>
    <message>
        <source>the store refused the checksum of part %1: %2</source>
        <translation>el almacén rechazó la suma de control de la pieza %1: %2</translation>
    </message>
    <message>
        <source>the store has schema version %1, newer than this program&apos;s %2: update TolTurn</source>
        <translation>el almacén tiene la versión de esquema %1, más nueva que la %2 de este programa: actualice TolTurn</translation>
    </message>
</context>
<context>
    <name>MeasurementStore</name>
    <message>
        <source>cannot open the measurement store %1: %2</source>
        <translation>no se puede abrir el almacén de mediciones %1: %2</translation>
    </message>
    <message>
        <source>Qt&apos;s SQLite driver is not installed (Debian: libqt6sql6-sqlite)</source>
        <translation>el controlador SQLite de Qt no está instalado (Debian: libqt6sql6-sqlite)</translation>
    </message>
    <message>
        <source>Qt&apos;s PostgreSQL driver is not installed (Debian: libqt6sql6-psql)</source>
        <translation>el controlador PostgreSQL de Qt no está instalado (Debian: libqt6sql6-psql)</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>no se puede crear la carpeta %1</translation>
    </message>
    <message>
        <source>cannot start a transaction</source>
        <translation>no se puede iniciar una transacción</translation>
    </message>
    <message>
        <source>cannot store the part</source>
        <translation>no se puede guardar la pieza</translation>
    </message>
    <message>
        <source>cannot store point %1</source>
        <translation>no se puede guardar el punto %1</translation>
    </message>
    <message>
        <source>cannot commit the part</source>
        <translation>no se puede confirmar la pieza</translation>
    </message>
    <message>
        <source>cannot read part %1</source>
        <translation>no se puede leer la pieza %1</translation>
    </message>
    <message>
        <source>the store has no part %1</source>
        <translation>el almacén no tiene la pieza %1</translation>
    </message>
    <message>
        <source>cannot read the points of part %1</source>
        <translation>no se pueden leer los puntos de la pieza %1</translation>
    </message>
    <message>
        <source>part %1 has a point of unknown quantity &quot;%2&quot;</source>
        <translation>la pieza %1 tiene un punto de magnitud desconocida «%2»</translation>
    </message>
    <message>
        <source>cannot list the parts</source>
        <translation>no se pueden listar las piezas</translation>
    </message>
    <message>
        <source>cannot count the parts</source>
        <translation>no se pueden contar las piezas</translation>
    </message>
    <message>
        <source>cannot remove part %1</source>
        <translation>no se puede eliminar la pieza %1</translation>
    </message>
    <message>
        <source>the store is not named</source>
        <translation>no se indica el almacén</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a PostgreSQL address of the form postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?host=SOCKET_FOLDER]</source>
        <translation>«%1» no es una dirección PostgreSQL de la forma postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE[?host=SOCKET_FOLDER]</translation>
    </message>
    <message>
        <source>a learned model needs its machine and finite figures</source>
        <translation>un modelo aprendido necesita su máquina y cifras finitas</translation>
    </message>
    <message>
        <source>cannot keep the learned model</source>
        <translation>no se puede guardar el modelo aprendido</translation>
    </message>
    <message>
        <source>cannot read the learned models</source>
        <translation>no se pueden leer los modelos aprendidos</translation>
    </message>
    <message>
        <source>part %1 has a damaged drive reading: %2</source>
        <translation>la pieza %1 tiene una lectura de accionamientos dañada: %2</translation>
    </message>
</context>
<context>
    <name>MeasurementsCommand</name>
    <message>
        <source>--%1 takes a number, not &quot;%2&quot;</source>
        <translation>--%1 espera un número, no «%2»</translation>
    </message>
    <message>
        <source>a part is named by its number from 1, not &quot;%1&quot;</source>
        <translation>una pieza se indica por su número desde 1, no «%1»</translation>
    </message>
    <message>
        <source>The measured points (feature, z_mm, diameter_mm or radial_deviation_um).</source>
        <translation>Los puntos medidos (feature, z_mm, diameter_mm o radial_deviation_um).</translation>
    </message>
    <message>
        <source>The machine the part was cut on (default: the project&apos;s).</source>
        <translation>La máquina en que se mecanizó la pieza (por defecto: la del proyecto).</translation>
    </message>
    <message>
        <source>When it was measured, ISO 8601 (default: now).</source>
        <translation>Cuándo se midió, ISO 8601 (por defecto: ahora).</translation>
    </message>
    <message>
        <source>Who measured it.</source>
        <translation>Quién la midió.</translation>
    </message>
    <message>
        <source>How: micrometer, CMM, bore gauge, …</source>
        <translation>Cómo: micrómetro, MMC, medidor de interiores, …</translation>
    </message>
    <message>
        <source>Minutes the machine had run when it was cut.</source>
        <translation>Minutos que llevaba la máquina en marcha al mecanizarla.</translation>
    </message>
    <message>
        <source>Ambient temperature when it was cut, °C.</source>
        <translation>Temperatura ambiente al mecanizarla, °C.</translation>
    </message>
    <message>
        <source>A note.</source>
        <translation>Una nota.</translation>
    </message>
    <message>
        <source>The project the part was cut from.</source>
        <translation>El proyecto del que se mecanizó la pieza.</translation>
    </message>
    <message>
        <source>Store a measured part.</source>
        <translation>Guardar una pieza medida.</translation>
    </message>
    <message>
        <source>give one project file and --csv FILE.csv</source>
        <translation>indique un archivo de proyecto y --csv FILE.csv</translation>
    </message>
    <message>
        <source>--at takes a time as 2026-11-24T08:30:00Z, not &quot;%1&quot;</source>
        <translation>--at espera una hora como 2026-11-24T08:30:00Z, no «%1»</translation>
    </message>
    <message numerus="yes">
        <source>stored part %1: %2, %n point(s), in %3</source>
        <translation>
            <numerusform>pieza %1 guardada: %2, %n punto, en %3</numerusform>
            <numerusform>pieza %1 guardada: %2, %n puntos, en %3</numerusform>
        </translation>
    </message>
    <message>
        <source>Only the parts of this machine.</source>
        <translation>Solo las piezas de esta máquina.</translation>
    </message>
    <message>
        <source>Only parts with this in their name, measurer or method.</source>
        <translation>Solo piezas con esto en su nombre, medidor o método.</translation>
    </message>
    <message>
        <source>At most N parts, newest first.</source>
        <translation>Como mucho N piezas, las más recientes primero.</translation>
    </message>
    <message>
        <source>Print the list as JSON.</source>
        <translation>Imprimir la lista como JSON.</translation>
    </message>
    <message>
        <source>List the stored parts, newest first.</source>
        <translation>Listar las piezas guardadas, las más recientes primero.</translation>
    </message>
    <message>
        <source>--limit takes a number from 1, not &quot;%1&quot;</source>
        <translation>--limit espera un número desde 1, no «%1»</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n punto</numerusform>
            <numerusform>%n puntos</numerusform>
        </translation>
    </message>
    <message>
        <source>The part&apos;s number.</source>
        <translation>El número de la pieza.</translation>
    </message>
    <message>
        <source>Remove a stored part with its points.</source>
        <translation>Eliminar una pieza guardada con sus puntos.</translation>
    </message>
    <message>
        <source>give the number of one part</source>
        <translation>indique el número de una pieza</translation>
    </message>
    <message>
        <source>removed part %1</source>
        <translation>pieza %1 eliminada</translation>
    </message>
    <message>
        <source>Every part of this machine.</source>
        <translation>Todas las piezas de esta máquina.</translation>
    </message>
    <message>
        <source>The CSV file to write (&apos;-&apos;, the default: standard output).</source>
        <translation>El archivo CSV a escribir («-», por defecto: salida estándar).</translation>
    </message>
    <message>
        <source>Parts by number.</source>
        <translation>Piezas por número.</translation>
    </message>
    <message>
        <source>Write stored parts&apos; points as CSV.</source>
        <translation>Escribir los puntos de las piezas guardadas como CSV.</translation>
    </message>
    <message>
        <source>give part numbers or --machine ID</source>
        <translation>indique números de pieza o --machine ID</translation>
    </message>
    <message>
        <source>The measurement history of the machines (an SQLite file or a shared PostgreSQL database): store a measured part with the project it was cut from, list, remove, export as CSV.</source>
        <translation>El historial de mediciones de las máquinas (un archivo SQLite o una base PostgreSQL compartida): guardar una pieza medida con el proyecto del que salió, listar, eliminar, exportar como CSV.</translation>
    </message>
    <message>
        <source>say add, list, remove or export, not &quot;%1&quot;</source>
        <translation>diga add, list, remove o export, no «%1»</translation>
    </message>
    <message>
        <source>not a JSON object (%1)</source>
        <translation>no es un objeto JSON (%1)</translation>
    </message>
    <message>
        <source>The spindle and feed drives&apos; readings during the finishing cut (JSON: spindle_current_A, spindle_idle_current_A, …; docs/learning.md).</source>
        <translation>Las lecturas de los accionamientos del husillo y de avance durante el corte de acabado (JSON: spindle_current_A, spindle_idle_current_A, …; docs/learning.md).</translation>
    </message>
</context>
<context>
    <name>MilledFeatureCheck</name>
    <message>
        <source>a milled feature needs an id</source>
        <translation>un elemento fresado necesita un id</translation>
    </message>
    <message>
        <source>z from %1 mm to %2 mm is not a range within the part, 0 to %3 mm</source>
        <translation>z de %1 mm a %2 mm no es un intervalo dentro de la pieza, de 0 a %3 mm</translation>
    </message>
    <message>
        <source>spindle speed: %1 rpm is not positive</source>
        <translation>velocidad del husillo: %1 rpm no es positiva</translation>
    </message>
    <message>
        <source>K_tc: %1 N/mm² is not positive</source>
        <translation>K_tc: %1 N/mm² no es positivo</translation>
    </message>
    <message>
        <source>the cutting coefficients have no source: the verdict rests on numbers nobody can trace</source>
        <translation>los coeficientes de corte no tienen fuente: el veredicto se basa en números que nadie puede rastrear</translation>
    </message>
    <message>
        <source>tolerance zone: %1 µm is not positive</source>
        <translation>zona de tolerancia: %1 µm no es positiva</translation>
    </message>
    <message>
        <source>a flatness has no datums (ISO 1101), found %1</source>
        <translation>una planitud no tiene referencias (ISO 1101); se ha encontrado %1</translation>
    </message>
    <message>
        <source>there is no datum &apos;%1&apos; in the project</source>
        <translation>no hay ninguna referencia «%1» en el proyecto</translation>
    </message>
    <message>
        <source>a %1 is one straight cut: its CL points are not used</source>
        <translation>un elemento %1 es un único corte recto: sus puntos CL no se usan</translation>
    </message>
    <message>
        <source>milled feature %1 is not evaluated: it lacks %2</source>
        <translation>el elemento fresado %1 no se evalúa: no tiene %2</translation>
    </message>
    <message>
        <source>id &apos;%1&apos; is already another milled feature&apos;s</source>
        <translation>el id &apos;%1&apos; ya es de otro elemento fresado</translation>
    </message>
    <message>
        <source>id &apos;%1&apos; is already a feature of the profile</source>
        <translation>el id &apos;%1&apos; ya es un elemento del perfil</translation>
    </message>
    <message>
        <source>tool diameter: %1 mm is not positive</source>
        <translation>diámetro de la herramienta: %1 mm no es positivo</translation>
    </message>
    <message>
        <source>flutes: %1 is not 1 to 12</source>
        <translation>filos: %1 no está entre 1 y 12</translation>
    </message>
    <message>
        <source>helix angle: %1° is not 0 to 60°</source>
        <translation>ángulo de hélice: %1° no está entre 0 y 60°</translation>
    </message>
    <message>
        <source>%1 is beyond ±%2 (TolTurn&apos;s bound)</source>
        <translation>%1 supera ±%2 (límite de TolTurn)</translation>
    </message>
</context>
<context>
    <name>MilledFeatureOutput</name>
    <message>
        <source>not evaluated: it lacks %1</source>
        <translation>no evaluado: sin %1</translation>
    </message>
    <message>
        <source>not evaluated: %1</source>
        <translation>no evaluado: %1</translation>
    </message>
    <message>
        <source>located</source>
        <translation>situada</translation>
    </message>
    <message>
        <source>floating</source>
        <translation>flotante</translation>
    </message>
    <message>
        <source>form error %1 µm of %2 µm (%3 zone): </source>
        <translation>error de forma %1 µm de %2 µm (zona %3): </translation>
    </message>
    <message>
        <source>passes by %1 µm</source>
        <translation>cumple con %1 µm de margen</translation>
    </message>
    <message>
        <source>fails by %1 µm</source>
        <translation>no cumple por %1 µm</translation>
    </message>
    <message>
        <source>; holds at a feed per tooth up to %1 mm</source>
        <translation>; cumple con un avance por diente de hasta %1 mm</translation>
    </message>
    <message>
        <source>Milled features (five-axis ball-end model, Öztürk &amp; Budak):</source>
        <translation>Elementos fresados (modelo de fresa de punta esférica en cinco ejes, Öztürk &amp; Budak):</translation>
    </message>
    <message>
        <source>z %1–%2 mm  </source>
        <translation>z %1–%2 mm  </translation>
    </message>
    <message>
        <source>the tool&apos;s modulus is not given: carbide&apos;s %1 N/mm² (MakeItFrom)</source>
        <translation>no se indica el módulo de la herramienta: se toma el del metal duro, %1 N/mm² (MakeItFrom)</translation>
    </message>
    <message>
        <source>; no feed up to the planned one holds</source>
        <translation>; ningún avance hasta el planificado la cumple</translation>
    </message>
</context>
<context>
    <name>MilledFeatures</name>
    <message>
        <source>path point %1: %2</source>
        <translation>punto %1 de la trayectoria: %2</translation>
    </message>
    <message>
        <source>the ball-end tool</source>
        <translation>la fresa de punta esférica</translation>
    </message>
    <message>
        <source>the holder&apos;s springs k and k_θ</source>
        <translation>los resortes k y k_θ del portaherramientas</translation>
    </message>
    <message>
        <source>the cutting conditions</source>
        <translation>las condiciones de corte</translation>
    </message>
    <message>
        <source>the cutting coefficients</source>
        <translation>los coeficientes de corte</translation>
    </message>
    <message>
        <source>the tolerance</source>
        <translation>la tolerancia</translation>
    </message>
    <message>
        <source>the tool path (at least two CL points)</source>
        <translation>la trayectoria de la herramienta (al menos dos puntos CL)</translation>
    </message>
    <message>
        <source>the tool axis is zero</source>
        <translation>el eje de la herramienta es nulo</translation>
    </message>
    <message>
        <source>the surface normal is zero</source>
        <translation>la normal a la superficie es nula</translation>
    </message>
    <message>
        <source>the tool axis points into the surface</source>
        <translation>el eje de la herramienta apunta hacia el interior de la superficie</translation>
    </message>
    <message>
        <source>the feed runs along the surface normal</source>
        <translation>el avance sigue la normal a la superficie</translation>
    </message>
    <message>
        <source>milled feature %1 lacks %2</source>
        <translation>el elemento fresado %1 no tiene %2</translation>
    </message>
    <message>
        <source>highest feed per tooth: %1 mm is not positive</source>
        <translation>mayor avance por diente: %1 mm no es positivo</translation>
    </message>
    <message>
        <source>a tool path has 2 to %1 CL points, this one %2</source>
        <translation>una trayectoria tiene de 2 a %1 puntos CL, esta %2</translation>
    </message>
    <message>
        <source>the ball is where it was at the point before</source>
        <translation>la bola está donde estaba en el punto anterior</translation>
    </message>
    <message>
        <source>the predicted deflection is not finite: the tool&apos;s data lie beyond what the model computes</source>
        <translation>la deflexión prevista no es finita: los datos de la herramienta quedan fuera de lo que el modelo calcula</translation>
    </message>
</context>
<context>
    <name>MillingCommand</name>
    <message>
        <source>Öztürk &amp; Budak&apos;s cut 1–4 (001 table 4): tool, cut and speed; the options below change it.</source>
        <translation>Corte 1–4 de Öztürk &amp; Budak (001 tabla 4): herramienta, corte y velocidad; las opciones de abajo lo cambian.</translation>
    </message>
    <message>
        <source>Ball diameter in mm.</source>
        <translation>Diámetro de la bola en mm.</translation>
    </message>
    <message>
        <source>Number of flutes.</source>
        <translation>Número de filos.</translation>
    </message>
    <message>
        <source>Helix angle in degrees (default 30).</source>
        <translation>Ángulo de hélice en grados (por defecto 30).</translation>
    </message>
    <message>
        <source>Lead angle in degrees (default 0).</source>
        <translation>Ángulo lead en grados (por defecto 0).</translation>
    </message>
    <message>
        <source>Tilt angle in degrees (default 0).</source>
        <translation>Ángulo tilt en grados (por defecto 0).</translation>
    </message>
    <message>
        <source>Axial depth of cut along the surface normal in mm.</source>
        <translation>Profundidad axial de corte a lo largo de la normal a la superficie en mm.</translation>
    </message>
    <message>
        <source>Side cut into uncut material this wide, in mm (table 1); without it or --step-over, a slot.</source>
        <translation>Corte lateral en material sin cortar de este ancho, en mm (tabla 1); sin esta opción ni --step-over, una ranura.</translation>
    </message>
    <message>
        <source>Cut beside a previous pass this far away, in mm (table 2).</source>
        <translation>Corte junto a una pasada anterior a esta distancia, en mm (tabla 2).</translation>
    </message>
    <message>
        <source>Up milling (default down milling).</source>
        <translation>Fresado en oposición (por defecto en concordancia).</translation>
    </message>
    <message>
        <source>Feed per tooth in mm.</source>
        <translation>Avance por diente en mm.</translation>
    </message>
    <message>
        <source>Spindle speed in 1/min.</source>
        <translation>Velocidad del husillo en 1/min.</translation>
    </message>
    <message>
        <source>The tool and material&apos;s cutting and edge coefficients Ktc,Krc,Kac (N/mm²),Kte,Kre,Kae (N/mm) of the linear edge-force model (001 eq. 11). Required: 001 prints none, and TolTurn&apos;s data library has none for ball-end milling.</source>
        <translation>Los coeficientes de corte y de filo Ktc,Krc,Kac (N/mm²),Kte,Kre,Kae (N/mm) de la herramienta y el material en el modelo lineal de fuerzas de filo (001 ec. 11). Obligatorios: 001 no publica ninguno y la biblioteca de datos de TolTurn no tiene ninguno para fresado con fresa de punta esférica.</translation>
    </message>
    <message>
        <source>Disc elements over the engaged height (default 200).</source>
        <translation>Elementos de disco en la altura en contacto (por defecto 200).</translation>
    </message>
    <message>
        <source>Rotation angles per revolution (default 360).</source>
        <translation>Ángulos de rotación por vuelta (por defecto 360).</translation>
    </message>
    <message>
        <source>Print the results as JSON.</source>
        <translation>Imprimir los resultados como JSON.</translation>
    </message>
    <message>
        <source>Print every rotation angle as CSV.</source>
        <translation>Imprimir cada ángulo de rotación como CSV.</translation>
    </message>
    <message>
        <source>give --radial-depth or --step-over, not both</source>
        <translation>indique --radial-depth o --step-over, no ambos</translation>
    </message>
    <message>
        <source>give --case N, or the tool and cut: %1 missing</source>
        <translation>indique --case N, o la herramienta y el corte: falta %1</translation>
    </message>
    <message>
        <source>--coefficients Ktc,Krc,Kac,Kte,Kre,Kae is required: Öztürk &amp; Budak print no coefficients (theirs come from an orthogonal-cutting database of Ti6Al4V through the oblique transformation), and TolTurn&apos;s data library has none for ball-end milling; give your tool and material&apos;s (docs/milling.md)</source>
        <translation>--coefficients Ktc,Krc,Kac,Kte,Kre,Kae es obligatorio: Öztürk &amp; Budak no publican coeficientes (los suyos vienen de una base de datos de corte ortogonal de Ti6Al4V mediante la transformación oblicua) y la biblioteca de datos de TolTurn no tiene ninguno para fresado con fresa de punta esférica; indique los de su herramienta y material (docs/milling.md)</translation>
    </message>
    <message>
        <source>--coefficients: &quot;%1&quot; is not six numbers Ktc,Krc,Kac,Kte,Kre,Kae of at most %2</source>
        <translation>--coefficients: «%1» no son seis números Ktc,Krc,Kac,Kte,Kre,Kae de como mucho %2</translation>
    </message>
    <message>
        <source>slot</source>
        <translation>ranura</translation>
    </message>
    <message>
        <source>side cut %1 mm wide</source>
        <translation>corte lateral de %1 mm de ancho</translation>
    </message>
    <message>
        <source>step-over %1 mm</source>
        <translation>paso lateral %1 mm</translation>
    </message>
    <message>
        <source>Öztürk &amp; Budak (001) table 4, case %1: DMU 50 Evolution, Ti6Al4V</source>
        <translation>Öztürk &amp; Budak (001) tabla 4, caso %1: DMU 50 Evolution, Ti6Al4V</translation>
    </message>
    <message>
        <source>Ball-end mill Ø%1 mm, %2 flutes, helix %3°; %4, %5 milling, axial depth %6 mm, feed %7 mm/tooth, %8 1/min; lead %9°, tilt %10°</source>
        <translation>Fresa de punta esférica Ø%1 mm, %2 filos, hélice %3°; %4, fresado %5, profundidad axial %6 mm, avance %7 mm/diente, %8 1/min; lead %9°, tilt %10°</translation>
    </message>
    <message>
        <source>down</source>
        <translation>en concordancia</translation>
    </message>
    <message>
        <source>up</source>
        <translation>en oposición</translation>
    </message>
    <message>
        <source>Coefficients (given): Ktc %1, Krc %2, Kac %3 N/mm²; Kte %4, Kre %5, Kae %6 N/mm</source>
        <translation>Coeficientes (indicados): Ktc %1, Krc %2, Kac %3 N/mm²; Kte %4, Kre %5, Kae %6 N/mm</translation>
    </message>
    <message>
        <source>%1 disc elements, %2 rotation angles per revolution</source>
        <translation>%1 elementos de disco, %2 ángulos de rotación por vuelta</translation>
    </message>
    <message>
        <source>Peak forces on the tool: F %1 N, C %2 N, N %3 N (feed, cross-feed, surface normal); resultant %4 N</source>
        <translation>Fuerzas máximas sobre la herramienta: F %1 N, C %2 N, N %3 N (avance, transversal, normal a la superficie); resultante %4 N</translation>
    </message>
    <message>
        <source>Torque: mean %1 N·m, peak %2 N·m; mean spindle power %3 W</source>
        <translation>Par: medio %1 N·m, máximo %2 N·m; potencia media del husillo %3 W</translation>
    </message>
    <message>
        <source>From where the holder grips the tool to its tip, in mm.</source>
        <translation>Desde donde el portaherramientas sujeta la herramienta hasta su punta, en mm.</translation>
    </message>
    <message>
        <source>Diameter of the cylinder that stands for the fluted tool in bending, in mm.</source>
        <translation>Diámetro del cilindro que representa a la herramienta con ranuras en flexión, en mm.</translation>
    </message>
    <message>
        <source>Young&apos;s modulus of the tool in N/mm² (default 630000, tungsten carbide; cemented carbides span 530000–700000).</source>
        <translation>Módulo de Young de la herramienta en N/mm² (por defecto 630000, carburo de wolframio; los metales duros van de 530000 a 700000).</translation>
    </message>
    <message>
        <source>The holder&apos;s springs k (N/mm) and k_θ (N·mm/rad) as K,KTHETA; with --case, 001&apos;s calibration 6306,1.656e7 for its tool.</source>
        <translation>Los resortes del portaherramientas k (N/mm) y k_θ (N·mm/rad) como K,KTHETA; con --case, la calibración de 001, 6306,1.656e7, para su herramienta.</translation>
    </message>
    <message>
        <source>the tool&apos;s structure is needed: %1 missing</source>
        <translation>se necesita la estructura de la herramienta: falta %1</translation>
    </message>
    <message>
        <source>--holder: &quot;%1&quot; is not two numbers K,KTHETA</source>
        <translation>--holder: «%1» no son dos números K,KTHETA</translation>
    </message>
    <message>
        <source>The surface&apos;s flatness or profile tolerance t in mm.</source>
        <translation>La tolerancia de planitud o de perfil t de la superficie en mm.</translation>
    </message>
    <message>
        <source>A profile tolerance with datums: every normal error within ±t/2 (default: a floating zone, the spread within t).</source>
        <translation>Una tolerancia de perfil con referencias: cada error normal dentro de ±t/2 (por defecto: una zona flotante, la dispersión dentro de t).</translation>
    </message>
    <message>
        <source>The largest feed per tooth the tool&apos;s maker allows, in mm.</source>
        <translation>El mayor avance por diente que permite el fabricante de la herramienta, en mm.</translation>
    </message>
    <message>
        <source>Leads to search, LO,HI in degrees (default -40,40).</source>
        <translation>Ángulos lead a explorar, LO,HI en grados (por defecto -40,40).</translation>
    </message>
    <message>
        <source>Tilts to search, LO,HI in degrees (default -40,40).</source>
        <translation>Ángulos tilt a explorar, LO,HI en grados (por defecto -40,40).</translation>
    </message>
    <message>
        <source>Leads and tilts of the window, each (default 64).</source>
        <translation>Ángulos lead y tilt de la ventana, cada uno (por defecto 64).</translation>
    </message>
    <message>
        <source>Threads (default 2).</source>
        <translation>Hilos (por defecto 2).</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not LO,HI in degrees with -60 &lt;= LO &lt; HI &lt;= 60</source>
        <translation>--%1: «%2» no es LO,HI en grados con -60 &lt;= LO &lt; HI &lt;= 60</translation>
    </message>
    <message>
        <source>--max-feed-per-tooth is required: the largest feed per tooth the tool&apos;s maker allows (TolTurn&apos;s data library has no ball-end mills)</source>
        <translation>--max-feed-per-tooth es obligatorio: el mayor avance por diente que permite el fabricante de la herramienta (la biblioteca de datos de TolTurn no tiene fresas de punta esférica)</translation>
    </message>
    <message>
        <source>Tolerance %1 µm, %2; feed per tooth up to %3 mm</source>
        <translation>Tolerancia %1 µm, %2; avance por diente hasta %3 mm</translation>
    </message>
    <message>
        <source>floating zone (flatness, or profile without datums): spread of the normal error</source>
        <translation>zona flotante (planitud, o perfil sin referencias): dispersión del error normal</translation>
    </message>
    <message>
        <source>located zone (profile with datums): normal error within ±t/2</source>
        <translation>zona situada (perfil con referencias): error normal dentro de ±t/2</translation>
    </message>
    <message>
        <source>Window %1 × %2: %3 cells with the cut on the ball, %4 of them hold the tolerance</source>
        <translation>Ventana %1 × %2: %3 celdas con el corte en la bola, %4 de ellas cumplen la tolerancia</translation>
    </message>
    <message>
        <source>No lead and tilt in the bounds holds the tolerance at any feed: the edge forces alone deflect the tool too far, or the cut does not stay on the ball.</source>
        <translation>Ningún lead ni tilt dentro de los límites cumple la tolerancia con ningún avance: las fuerzas de filo por sí solas flexionan demasiado la herramienta, o el corte no queda en la bola.</translation>
    </message>
    <message>
        <source>Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min); form error %5 µm (%6 NLopt Subplex evaluations after the window)</source>
        <translation>Plan: lead %1°, tilt %2°, avance %3 mm/diente (%4 mm/min); error de forma %5 µm (%6 evaluaciones de NLopt Subplex tras la ventana)</translation>
    </message>
    <message>
        <source>Five-axis ball-end milling forces over a revolution (Öztürk &amp; Budak): on the tool in feed, cross-feed and normal directions, torque and spindle power.</source>
        <translation>Fuerzas del fresado en cinco ejes con fresa de punta esférica durante una vuelta (Öztürk &amp; Budak): sobre la herramienta en las direcciones de avance, transversal y normal, par y potencia del husillo.</translation>
    </message>
    <message>
        <source>give --json or --csv, not both</source>
        <translation>indique --json o --csv, no ambos</translation>
    </message>
    <message>
        <source>The ball-end mill&apos;s deflection over a revolution and the surface error along the normal it leaves (Öztürk &amp; Budak table 3): the tool a cantilever on springs k, k_θ.</source>
        <translation>La flexión de la fresa de punta esférica durante una vuelta y el error de superficie a lo largo de la normal que deja (Öztürk &amp; Budak tabla 3): la herramienta, una viga en voladizo sobre resortes k, k_θ.</translation>
    </message>
    <message>
        <source>Tool: overhang %1 mm, a Ø%2 mm cylinder of E = %3 N/mm², holder k = %4 N/mm, k_θ = %5 N·mm/rad%6</source>
        <translation>Herramienta: voladizo %1 mm, un cilindro de Ø%2 mm con E = %3 N/mm², portaherramientas k = %4 N/mm, k_θ = %5 N·mm/rad%6</translation>
    </message>
    <message>
        <source> (001&apos;s calibration for its tool)</source>
        <translation> (calibración de 001 para su herramienta)</translation>
    </message>
    <message>
        <source>Surface error along the normal, over a revolution: %1 to %2 µm (positive: material left); generating point %3 mm up the axis. Only the tool deflects in this model.</source>
        <translation>Error de superficie a lo largo de la normal durante una vuelta: de %1 a %2 µm (positivo: queda material); punto generador a %3 mm eje arriba. En este modelo solo se flexiona la herramienta.</translation>
    </message>
    <message>
        <source>The lead, tilt and feed per tooth of least machining time that keep the ball-end surface within its flatness or profile tolerance, with the lead–tilt window.</source>
        <translation>El lead, el tilt y el avance por diente de menor tiempo de mecanizado que mantienen la superficie fresada dentro de su tolerancia de planitud o de perfil, con la ventana lead–tilt.</translation>
    </message>
    <message>
        <source>--tolerance is required: the surface&apos;s tolerance t in mm</source>
        <translation>--tolerance es obligatorio: la tolerancia t de la superficie en mm</translation>
    </message>
    <message>
        <source>takes a project file only with --feature ID: &quot;%1&quot;</source>
        <translation>solo admite un archivo de proyecto con --feature ID: «%1»</translation>
    </message>
    <message>
        <source>--feature needs the project file PROJECT it is in</source>
        <translation>--feature necesita el archivo de proyecto PROJECT en el que está</translation>
    </message>
    <message>
        <source>With --feature: write the plan (lead, tilt, feed per tooth) into the feature&apos;s conditions in PROJECT.</source>
        <translation>Con --feature: escribir el plan (lead, tilt, avance por diente) en las condiciones del elemento en PROJECT.</translation>
    </message>
    <message>
        <source>--tolerance, --located: the tolerance comes from the project&apos;s feature; change it there</source>
        <translation>--tolerance, --located: la tolerancia viene del elemento del proyecto; cámbiela allí</translation>
    </message>
    <message>
        <source>--save: no plan holds the tolerance; %1 is left as it was</source>
        <translation>--save: ningún plan cumple la tolerancia; %1 queda como estaba</translation>
    </message>
    <message>
        <source>No feed holds the tolerance along the path: the edge forces alone deflect the tool too far at its tool axes.</source>
        <translation>Ningún avance cumple la tolerancia a lo largo de la trayectoria: las fuerzas de filo por sí solas flexionan demasiado la herramienta con los ejes de la herramienta de la trayectoria.</translation>
    </message>
    <message>
        <source>Plan along the path&apos;s own tool axes: feed %1 mm/tooth (%2 mm/min); form error %3 µm</source>
        <translation>Plan con los propios ejes de la herramienta de la trayectoria: avance %1 mm/diente (%2 mm/min); error de forma %3 µm</translation>
    </message>
    <message>
        <source>--save needs PROJECT --feature ID</source>
        <translation>--save necesita PROJECT --feature ID</translation>
    </message>
    <message>
        <source>%1: the tool and cut come from the project&apos;s feature; change them there</source>
        <translation>%1: la herramienta y el corte vienen del elemento del proyecto; cámbielos allí</translation>
    </message>
    <message>
        <source>--feature: there is no milled feature &quot;%1&quot; in %2</source>
        <translation>--feature: no hay ningún elemento fresado «%1» en %2</translation>
    </message>
    <message>
        <source>milled feature %1 lacks %2</source>
        <translation>el elemento fresado %1 no tiene %2</translation>
    </message>
    <message>
        <source>--%1: the tool&apos;s structure comes from the project&apos;s feature; change it there</source>
        <translation>--%1: la estructura de la herramienta viene del elemento del proyecto; cámbiela allí</translation>
    </message>
    <message>
        <source>The milled feature of the project PROJECT to compute, with its tool, cut, coefficients and tolerance.</source>
        <translation>El elemento fresado del proyecto PROJECT que se calcula, con su herramienta, corte, coeficientes y tolerancia.</translation>
    </message>
    <message>
        <source>With --feature, a patch&apos;s CL point to compute at (default 1; mill-optimize plans the whole path).</source>
        <translation>Con --feature, el punto CL del parche en el que se calcula (por defecto 1; mill-optimize planifica toda la trayectoria).</translation>
    </message>
    <message>
        <source>The plan is saved in %1, feature %2 (the feed per tooth rounded down to 0.0001 mm).</source>
        <translation>El plan se ha guardado en %1, elemento %2 (avance por diente redondeado hacia abajo a 0,0001 mm).</translation>
    </message>
    <message>
        <source>--save plans at evaluate&apos;s resolution (200 slices, 360 angles): leave out --slices and --angles</source>
        <translation>--save planifica con la resolución de evaluate (200 rodajas, 360 ángulos): omita --slices y --angles</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>aviso: %1</translation>
    </message>
</context>
<context>
    <name>MillingReport</name>
    <message>
        <source>Ø%1 mm, 1 flute, helix %2°</source>
        <translation>Ø%1 mm, 1 filo, hélice %2°</translation>
    </message>
    <message>
        <source>Ø%1 mm, %2 flutes, helix %3°</source>
        <translation>Ø%1 mm, %2 filos, hélice %3°</translation>
    </message>
    <message>
        <source>down milling</source>
        <translation>fresado en concordancia</translation>
    </message>
    <message>
        <source>up milling</source>
        <translation>fresado en oposición</translation>
    </message>
    <message>
        <source>, s %1 mm</source>
        <translation>, s %1 mm</translation>
    </message>
    <message>
        <source>; f_z %1 mm; %2 rpm; </source>
        <translation>; f_z %1 mm; %2 rpm; </translation>
    </message>
    <message>
        <source>lead and tilt from the path</source>
        <translation>lead y tilt según la trayectoria</translation>
    </message>
    <message>
        <source>lead %1°, tilt %2°</source>
        <translation>lead %1°, tilt %2°</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>perfil</translation>
    </message>
    <message>
        <source>flatness</source>
        <translation>planitud</translation>
    </message>
    <message>
        <source>located, datums %1</source>
        <translation>situada, referencias %1</translation>
    </message>
    <message>
        <source>floating</source>
        <translation>flotante</translation>
    </message>
    <message>
        <source>%1 %2 µm, %3</source>
        <translation>%1 %2 µm, %3</translation>
    </message>
    <message>
        <source>not evaluated: lacks %1</source>
        <translation>no evaluado: sin %1</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>rechazado: %1</translation>
    </message>
    <message>
        <source>passes by %1 µm</source>
        <translation>cumple con %1 µm de margen</translation>
    </message>
    <message>
        <source>largest f_z that holds: %1 mm</source>
        <translation>mayor f_z que cumple: %1 mm</translation>
    </message>
    <message>
        <source>no f_z up to the planned one holds</source>
        <translation>ningún f_z hasta el planificado cumple</translation>
    </message>
    <message>
        <source>fails by %1 µm; %2</source>
        <translation>no cumple por %1 µm; %2</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <source>Conditions</source>
        <translation>Condiciones</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Form error [µm]</source>
        <translation>Error de forma [µm]</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <source>E of the tool not given: carbide&apos;s %1 N/mm² (MakeItFrom)</source>
        <translation>E de la herramienta no indicado: se toma el del metal duro, %1 N/mm² (MakeItFrom)</translation>
    </message>
    <message>
        <source>coefficients without a source</source>
        <translation>coeficientes sin fuente</translation>
    </message>
    <message>
        <source>coefficients: %1</source>
        <translation>coeficientes: %1</translation>
    </message>
    <message>
        <source>δ_N, least</source>
        <translation>δ_N, mínimo</translation>
    </message>
    <message>
        <source>δ_N, greatest</source>
        <translation>δ_N, máximo</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>zona, inferior</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>zona, superior</translation>
    </message>
    <message>
        <source>arc length along the path [mm]</source>
        <translation>longitud de arco a lo largo de la trayectoria [mm]</translation>
    </message>
    <message>
        <source>surface-normal error δ_N [µm]</source>
        <translation>error normal a la superficie δ_N [µm]</translation>
    </message>
    <message>
        <source>%1: surface-normal error along the path (%2 zone)</source>
        <translation>%1: error normal a la superficie a lo largo de la trayectoria (zona %2)</translation>
    </message>
    <message>
        <source>located</source>
        <translation>situada</translation>
    </message>
    <message>
        <source>%1: largest force on the tool %2 N, mean torque %3 N·m, spindle power %4 W.</source>
        <translation>%1: fuerza máxima sobre la herramienta %2 N, par medio %3 N·m, potencia del husillo %4 W.</translation>
    </message>
    <message>
        <source>Each milled feature is evaluated with Öztürk &amp; Budak&apos;s ball-end model [9]: the forces bend the tool and leave the surface-normal error δ_N (its range over a revolution at each point of the path). The form error is the spread of δ_N along the path for a floating zone, twice its largest magnitude for a located one (ISO 1101 [6]).</source>
        <translation>Cada elemento fresado se evalúa con el modelo de fresa de punta esférica de Öztürk &amp; Budak [9]: las fuerzas flexionan la herramienta y dejan el error normal a la superficie δ_N (su rango durante una vuelta en cada punto de la trayectoria). El error de forma es la dispersión de δ_N a lo largo de la trayectoria para una zona flotante, y el doble de su mayor magnitud para una zona situada (ISO 1101 [6]).</translation>
    </message>
</context>
<context>
    <name>ModelFiles</name>
    <message>
        <source>model form</source>
        <translation>forma del modelo</translation>
    </message>
    <message>
        <source>a coefficient must be a number, not %1</source>
        <translation>un coeficiente debe ser un número, no %1</translation>
    </message>
    <message numerus="yes">
        <source>a %1 model does not take %n coefficient(s)</source>
        <translation>
            <numerusform>un modelo %1 no admite %n coeficiente</numerusform>
            <numerusform>un modelo %1 no admite %n coeficientes</numerusform>
        </translation>
    </message>
    <message>
        <source>file format</source>
        <translation>formato de archivo</translation>
    </message>
    <message>
        <source>version %1 is not one this TolTurn reads (1)</source>
        <translation>esta versión de TolTurn no lee la versión %1 (1)</translation>
    </message>
    <message>
        <source>cannot be read: %1</source>
        <translation>no se puede leer: %1</translation>
    </message>
    <message>
        <source>not a valid JSON object: %1</source>
        <translation>no es un objeto JSON válido: %1</translation>
    </message>
</context>
<context>
    <name>Names</name>
    <message>
        <source>chuck</source>
        <translation>plato</translation>
    </message>
    <message>
        <source>between centres</source>
        <translation>entre puntos</translation>
    </message>
    <message>
        <source>chuck + tailstock</source>
        <translation>plato + contrapunto</translation>
    </message>
    <message>
        <source>cylinder</source>
        <translation>cilindro</translation>
    </message>
    <message>
        <source>face</source>
        <translation>cara</translation>
    </message>
    <message>
        <source>cone</source>
        <translation>cono</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>chaflán</translation>
    </message>
    <message>
        <source>radius</source>
        <translation>radio</translation>
    </message>
    <message>
        <source>length</source>
        <translation>longitud</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>diámetro</translation>
    </message>
    <message>
        <source>flatness</source>
        <translation>planitud</translation>
    </message>
    <message>
        <source>cylindricity</source>
        <translation>cilindricidad</translation>
    </message>
    <message>
        <source>profile of a surface</source>
        <translation>perfil de una superficie</translation>
    </message>
    <message>
        <source>parallelism</source>
        <translation>paralelismo</translation>
    </message>
    <message>
        <source>perpendicularity</source>
        <translation>perpendicularidad</translation>
    </message>
    <message>
        <source>coaxiality</source>
        <translation>coaxialidad</translation>
    </message>
    <message>
        <source>circular radial run-out</source>
        <translation>oscilación circular radial</translation>
    </message>
    <message>
        <source>circular axial run-out</source>
        <translation>oscilación circular axial</translation>
    </message>
    <message>
        <source>total radial run-out</source>
        <translation>oscilación total radial</translation>
    </message>
    <message>
        <source>total axial run-out</source>
        <translation>oscilación total axial</translation>
    </message>
    <message>
        <source>left</source>
        <translation>izquierdo</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecho</translation>
    </message>
    <message>
        <source>collet</source>
        <translation>pinza</translation>
    </message>
    <message>
        <source>flat</source>
        <translation>cara plana</translation>
    </message>
    <message>
        <source>keyway</source>
        <translation>chavetero</translation>
    </message>
    <message>
        <source>surface patch</source>
        <translation>parche de superficie</translation>
    </message>
    <message>
        <source>slot</source>
        <translation>ranura</translation>
    </message>
    <message>
        <source>side cut</source>
        <translation>corte lateral</translation>
    </message>
    <message>
        <source>step-over</source>
        <translation>paso lateral</translation>
    </message>
</context>
<context>
    <name>Operations</name>
    <message>
        <source>another set-up</source>
        <translation>otro montaje</translation>
    </message>
    <message>
        <source>datum %1 on %2 is cut in %3</source>
        <translation>la referencia %1 en %2 se mecaniza en %3</translation>
    </message>
    <message>
        <source>%1 is cut in %2</source>
        <translation>%1 se mecaniza en %2</translation>
    </message>
    <message>
        <source>spans set-ups: %1, %2 in %3; clamping again adds 0–%4 µm (%5)</source>
        <translation>abarca varios montajes: %1, %2 en %3; volver a sujetar añade 0–%4 µm (%5)</translation>
    </message>
    <message>
        <source>; it holds with the largest of it</source>
        <translation>; se cumple incluso con el valor máximo</translation>
    </message>
    <message>
        <source>; it holds only if the re-clamping error stays below %1 µm</source>
        <translation>; solo se cumple si el error de re-sujeción se mantiene por debajo de %1 µm</translation>
    </message>
    <message>
        <source>; it fails even without it</source>
        <translation>; no se cumple ni siquiera sin él</translation>
    </message>
    <message>
        <source>feature %1 lies in the jaws of %2 (%3 mm from its held end): no tool reaches it there; name it in an operation that holds the other end</source>
        <translation>el elemento %1 está dentro de las garras en %2 (a %3 mm de su extremo sujetado): ninguna herramienta llega allí; inclúyalo en una operación que sujete el otro extremo</translation>
    </message>
    <message>
        <source>an operation needs a name</source>
        <translation>una operación necesita un nombre</translation>
    </message>
    <message>
        <source>two operations are named &quot;%1&quot;</source>
        <translation>dos operaciones se llaman &quot;%1&quot;</translation>
    </message>
    <message>
        <source>operation &quot;%1&quot; cuts no feature</source>
        <translation>la operación &quot;%1&quot; no mecaniza ningún elemento</translation>
    </message>
    <message>
        <source>there is no feature &quot;%1&quot;</source>
        <translation>no existe ningún elemento &quot;%1&quot;</translation>
    </message>
    <message>
        <source>feature %1 is named by two operations</source>
        <translation>el elemento %1 figura en dos operaciones</translation>
    </message>
    <message>
        <source>the part is not held in a chuck in one set-up</source>
        <translation>la pieza no está sujeta en un plato en un solo montaje</translation>
    </message>
    <message>
        <source>no feature lies in the jaws</source>
        <translation>ningún elemento queda en las garras</translation>
    </message>
    <message>
        <source>there is no outer cylinder to hold the part by at its other end</source>
        <translation>no hay un cilindro exterior por el que sujetar la pieza en su otro extremo</translation>
    </message>
    <message>
        <source>the jaws of %2 (%3 mm) cover %1: turn the part end for end and hold it %4 mm on %5 Ø%6, finished in %2, to turn them in %7</source>
        <translation>las garras de %2 (%3 mm) cubren %1: voltee la pieza y sujétela %4 mm por %5 Ø%6, acabado en %2, para tornearlos en %7</translation>
    </message>
    <message>
        <source>%1 cuts no feature: the later operations name them all</source>
        <translation>%1 no mecaniza ningún elemento: las operaciones posteriores los nombran todos</translation>
    </message>
    <message>
        <source>feature %1 is in the bore that opens at the end %2 holds: no tool reaches it there; name it in an operation that holds the other end</source>
        <translation>el elemento %1 está en el agujero que se abre en el extremo que sujeta %2: ninguna herramienta llega allí; inclúyalo en una operación que sujete el otro extremo</translation>
    </message>
    <message>
        <source>, a chuck&apos;s figure: no collet maker&apos;s is in the data</source>
        <translation>, un valor de plato: no hay ninguno de un fabricante de pinzas en los datos</translation>
    </message>
</context>
<context>
    <name>Optimiser</name>
    <message>
        <source>The search stopped at its time limit of %1 s after %2 plans: the plan shown is the best found by then, not necessarily the optimum.</source>
        <translation>La búsqueda se detuvo en su límite de tiempo de %1 s tras %2 planes: el plan mostrado es el mejor hallado hasta entonces, no necesariamente el óptimo.</translation>
    </message>
    <message>
        <source>On the section its own finishing depth (%1 mm) leaves, the plan the search found violated %2 %3; the speeds and feeds were searched again at depth %4 mm.</source>
        <translation>En la sección que deja su propia profundidad de acabado (%1 mm), el plan encontrado incumplía %2 %3; la velocidad de corte y el avance se buscaron de nuevo a la profundidad de %4 mm.</translation>
    </message>
    <message>
        <source>Stated on the steps a program gives them (%1 m/min, %2 mm/rev, %3 mm), the plan breaks a constraint: it is kept at full precision, and the program rounds it.</source>
        <translation>Llevado a los pasos en que un programa los indica (%1 m/min, %2 mm/rev, %3 mm), el plan incumple una restricción: se mantiene con precisión completa y el programa lo redondea.</translation>
    </message>
    <message>
        <source>The range %1–%2 %5 holds no value on the step a program states (%3 %5): the plan keeps %4 %5, which the program rounds.</source>
        <translation>El rango %1–%2 %5 no contiene ningún valor en el paso en que un programa lo indica (%3 %5): el plan mantiene %4 %5, que el programa redondea.</translation>
    </message>
</context>
<context>
    <name>Planning</name>
    <message>
        <source>tolerance %1</source>
        <translation>tolerancia %1</translation>
    </message>
    <message>
        <source>the optimiser needs the insert&apos;s ranges of cutting speed, feed and depth of cut (from its maker&apos;s catalogue), with their source</source>
        <translation>el optimizador necesita los intervalos de velocidad de corte, avance y profundidad de corte de la plaquita (del catálogo del fabricante), con su fuente</translation>
    </message>
    <message>
        <source>No Taylor constants in the project&apos;s planning data: tool life and tool cost are not in the objective, and there is no tool-life constraint.</source>
        <translation>No hay constantes de Taylor en los datos de planificación del proyecto: la vida y el coste de la herramienta no entran en el objetivo y no hay restricción de vida de la herramienta.</translation>
    </message>
    <message>
        <source>No spindle torque limit given (planning.max_torque_Nm): torque is not constrained.</source>
        <translation>No se ha indicado ningún límite de par del husillo (planning.max_torque_Nm): el par no está restringido.</translation>
    </message>
    <message>
        <source>No spindle power limit known (machine data or planning.max_power_kW): power is not constrained.</source>
        <translation>No se conoce límite de potencia del husillo (datos de la máquina o planning.max_power_kW): la potencia no está restringida.</translation>
    </message>
    <message>
        <source>No spindle speed limit known (machine data or planning.max_spindle_speed_rpm): spindle speed is not constrained.</source>
        <translation>No se conoce límite de velocidad del husillo (datos de la máquina o planning.max_spindle_speed_rpm): la velocidad no está restringida.</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius: at least %2 roughing passes at the insert&apos;s largest depth of cut (%3 mm), and the optimiser plans up to %4; turn from a smaller bar</source>
        <translation>el bruto deja %1 mm que quitar en el radio: al menos %2 pasadas de desbaste a la mayor profundidad de corte de la plaquita (%3 mm), y el optimizador planifica hasta %4; tornee a partir de una barra menor</translation>
    </message>
    <message>
        <source>The tolerance constraints include what was learned of the machine from its measured parts (%1); parts not learned from were predicted to %2 µm RMS.</source>
        <translation>Las restricciones de tolerancia incluyen lo aprendido de la máquina a partir de sus piezas medidas (%1); las piezas no aprendidas se predijeron a %2 µm RMS.</translation>
    </message>
    <message>
        <source>least cost needs the machine and operator rate per minute, but it is %1</source>
        <translation>el coste mínimo necesita la tarifa de máquina y operario por minuto, pero es %1</translation>
    </message>
    <message>
        <source>with a predicted value that is not finite</source>
        <translation>con un valor previsto que no es finito</translation>
    </message>
    <message>
        <source>by %1 %</source>
        <translation>en un %1 %</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius of the outer profile, less than the insert&apos;s smallest depth of cut (%2 mm, planning.ranges.depth_of_cut_mm): no pass can take it</source>
        <translation>el material en bruto deja %1 mm por quitar en el radio del perfil exterior, menos que la menor profundidad de corte de la plaquita (%2 mm, planning.ranges.depth_of_cut_mm): ninguna pasada puede quitarlo</translation>
    </message>
    <message>
        <source>the stock leaves %1 mm to remove on the radius, between what %2 and %3 passes at depths of cut from %4 to %5 mm (planning.ranges.depth_of_cut_mm) can take: at most %6 mm, at least %7 mm</source>
        <translation>el material en bruto deja %1 mm por quitar en el radio, entre lo que pueden quitar %2 y %3 pasadas con profundidades de corte de %4 a %5 mm (planning.ranges.depth_of_cut_mm): como mucho %6 mm, como mínimo %7 mm</translation>
    </message>
    <message>
        <source>The program has no finishing moves (see the G-code&apos;s warnings): the finishing time is taken as zero.</source>
        <translation>El programa no tiene movimientos de acabado (vea los avisos del código G): el tiempo de acabado se toma como cero.</translation>
    </message>
    <message>
        <source>The bores are not in the finishing time: the program does not bore them (see the G-code&apos;s notes).</source>
        <translation>Los agujeros no están en el tiempo de acabado: el programa no los mandrina (vea las notas del código G).</translation>
    </message>
    <message>
        <source>Not among the plan&apos;s constraints: %1.</source>
        <translation>No está entre las restricciones del plan: %1.</translation>
    </message>
    <message>
        <source>%1, the boring bar&apos;s insert</source>
        <translation>%1, la plaquita de la barra de mandrinar</translation>
    </message>
</context>
<context>
    <name>Plausibility</name>
    <message>
        <source>unknown material &quot;%1&quot;; the data library has: %2</source>
        <translation>material desconocido «%1»; la biblioteca de datos tiene: %2</translation>
    </message>
    <message>
        <source>unknown machine &quot;%1&quot;; the data library has: %2</source>
        <translation>máquina desconocida «%1»; la biblioteca de datos tiene: %2</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library and its ISO 5608 style letter (third character) gives no known entering angle</source>
        <translation>el portaherramientas «%1» no está en la biblioteca de datos y su letra de forma ISO 5608 (tercer carácter) no da ningún ángulo de posición conocido</translation>
    </message>
    <message>
        <source>holder &quot;%1&quot; is not in the data library: its entering angle comes from its ISO 5608 style letter, and its shank is not in the toolpost term</source>
        <translation>el portaherramientas «%1» no está en la biblioteca de datos: su ángulo de posición sale de su letra de forma ISO 5608 y su mango no entra en el término de la torreta</translation>
    </message>
    <message>
        <source>%1 %2 is outside the insert&apos;s published range %3–%4 %2 (%5)</source>
        <translation>%1 %2 está fuera del rango publicado de la plaquita %3–%4 %2 (%5)</translation>
    </message>
    <message>
        <source>no source given</source>
        <translation>sin fuente</translation>
    </message>
    <message>
        <source>%1 m/min on Ø%2 mm needs %3 rpm, more than the machine&apos;s %4 rpm: the spindle speed limit lowers the cutting speed there</source>
        <translation>%1 m/min en Ø%2 mm necesita %3 rpm, más que las %4 rpm de la máquina: el límite de velocidad reduce allí la velocidad de corte</translation>
    </message>
    <message>
        <source>the pass needs %1 kW of cutting power, more than the machine&apos;s %2 kW</source>
        <translation>la pasada necesita %1 kW de potencia de corte, más que los %2 kW de la máquina</translation>
    </message>
    <message>
        <source>the passes cut %1 mm deep in all, but the stock is at most %2 mm thick on the radius (Ø%3 mm bar, smallest turned Ø%4 mm): the tool cuts air for %5 mm, and the forces and deflection are not those of the passes as given</source>
        <translation>las pasadas cortan %1 mm de profundidad en total, pero el sobreespesor es como mucho de %2 mm en el radio (barra de Ø%3 mm, menor Ø torneado %4 mm): la herramienta corta aire durante %5 mm, y las fuerzas y la flexión no son las de las pasadas indicadas</translation>
    </message>
    <message>
        <source>the part has bores but no boring bar is given: they are computed as if cut by %1, without the bending of a bar</source>
        <translation>la pieza tiene agujeros pero no se ha indicado barra de mandrinar: se calculan como si los mecanizara %1, sin la flexión de una barra</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar in the data library; it has: %2</source>
        <translation>&quot;%1&quot; no es una barra de mandrinar de la biblioteca de datos; contiene: %2</translation>
    </message>
    <message>
        <source>the bar material of &quot;%1&quot; (type letter %2) is not in the data library</source>
        <translation>el material de la barra de &quot;%1&quot; (letra de tipo %2) no está en la biblioteca de datos</translation>
    </message>
    <message>
        <source>%1 mm is %2 times the bar&apos;s diameter, more than the %3 times the maker allows a %4 bar (%5): expect chatter; use a carbide or a larger bar, or bore from both ends</source>
        <translation>%1 mm es %2 veces el diámetro de la barra, más de las %3 veces que el fabricante permite a una barra de %4 (%5): cabe esperar vibraciones; use una barra de metal duro o más gruesa, o mandrine desde ambos extremos</translation>
    </message>
    <message>
        <source>a boring bar is given but no bore is cut</source>
        <translation>se ha indicado una barra de mandrinar, pero no se mecaniza ningún agujero</translation>
    </message>
    <message>
        <source>the groove between %1 and %2 is %3 mm wide, narrower than the nose of %4 (r_e %5 mm, %6 mm across): it cannot reach the groove&apos;s bottom; cut the groove with a grooving insert at most %3 mm wide</source>
        <translation>la ranura entre %1 y %2 tiene %3 mm de ancho, menos que la punta de %4 (r_e %5 mm, %6 mm de ancho): no puede llegar al fondo de la ranura; mecanice la ranura con una plaquita de ranurar de %3 mm de ancho como máximo</translation>
    </message>
    <message>
        <source>an edge %1 mm off the bar&apos;s axis cannot cut inside a bore: the widest is Ø%2 mm</source>
        <translation>un filo a %1 mm del eje de la barra no puede cortar dentro de un agujero: el mayor es de Ø%2 mm</translation>
    </message>
    <message>
        <source>a pilot hole of Ø%1 mm leaves nothing to bore in %2, Ø%3 mm</source>
        <translation>un agujero previo de Ø%1 mm no deja nada que mandrinar en %2, Ø%3 mm</translation>
    </message>
    <message>
        <source>no finishing pass: the last pass is taken as the one that cuts the contour to size (the verdicts and the program rest on it)</source>
        <translation>ninguna pasada de acabado: la última pasada se toma como la que lleva el contorno a medida (los veredictos y el programa se basan en ella)</translation>
    </message>
    <message>
        <source>left at the pilot hole</source>
        <translation>queda en el agujero previo</translation>
    </message>
    <message>
        <source>inside the jaws (left of z = %1 mm), where no verdict judges it</source>
        <translation>dentro de las garras (a la izquierda de z = %1 mm), donde ningún veredicto lo juzga</translation>
    </message>
    <message>
        <source>while the verdicts of %1 take it as bored</source>
        <translation>mientras que los veredictos de %1 lo toman como mandrinado</translation>
    </message>
    <message>
        <source>%1 mm reaches z = %2 mm (the free end at %3 mm, %4 mm clear of it): %5 not bored from z = %6 mm to there, %7. Reaching it needs an overhang of %8 mm; or bore from both ends</source>
        <translation>%1 mm llega hasta z = %2 mm (el extremo libre en %3 mm, a %4 mm de él): %5 sin mandrinar desde z = %6 mm hasta allí, %7. Para alcanzarlo hace falta un voladizo de %8 mm; o mandrinar desde ambos extremos</translation>
    </message>
    <message>
        <source>bore %1</source>
        <translation>agujero %1</translation>
    </message>
    <message>
        <source>bores %1</source>
        <translation>agujeros %1</translation>
    </message>
</context>
<context>
    <name>PlotExport</name>
    <message>
        <source>cannot export a plot as &apos;%1&apos;: use .png, .svg or .pdf</source>
        <translation>no se puede exportar un gráfico como &apos;%1&apos;: use .png, .svg o .pdf</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>Imagen PNG (*.png);;Dibujo SVG (*.svg);;Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Copy Data as CSV</source>
        <translation>Copiar datos como CSV</translation>
    </message>
    <message>
        <source>Export Image…</source>
        <translation>Exportar imagen…</translation>
    </message>
    <message>
        <source>Export Plot</source>
        <translation>Exportar gráfico</translation>
    </message>
</context>
<context>
    <name>PostProcessor</name>
    <message>
        <source>Path of the imaginary tool tip for nose radius %1 mm, computed by TolTurn: no G41/G42; set the nose radius to 0 in the tool offsets</source>
        <translation>Trayectoria de la punta teórica para un radio de punta de %1 mm, calculada por TolTurn: sin G41/G42; ponga el radio de punta a 0 en las correcciones de herramienta</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 3</source>
        <translation>G42 compensación del radio de punta: filo D1 con radio %1 mm, posición de filo 3</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: tool table diameter D%1, orientation Q2</source>
        <translation>G42 compensación del radio de punta: tabla de herramientas diámetro D%1, orientación Q2</translation>
    </message>
    <message>
        <source>G42 nose radius compensation: radius %1 mm and tip 3 in the tool geometry offset</source>
        <translation>G42 compensación del radio de punta: radio %1 mm y punta 3 en la corrección de geometría</translation>
    </message>
    <message>
        <source>Pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</source>
        <translation>Pasada %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>acabado</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>desbaste</translation>
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
        <translation>Velocidad máxima que necesita el plan: vc %1 m/min en D%2 mm</translation>
    </message>
    <message>
        <source>Machine limit %1 rpm; the plan would need %2 rpm on D%3 mm</source>
        <translation>Límite de la máquina %1 rpm; el plan necesitaría %2 rpm en D%3 mm</translation>
    </message>
    <message>
        <source>; machine limit %1 rpm</source>
        <translation>; límite de la máquina %1 rpm</translation>
    </message>
    <message>
        <source>; the machine&apos;s limit is not known</source>
        <translation>; no se conoce el límite de la máquina</translation>
    </message>
    <message>
        <source>Z0 at the right end face, X on diameter, G02/G03 seen with Z to the right and X up</source>
        <translation>Z0 en la cara frontal derecha, X en diámetro, G02/G03 vistos con Z a la derecha y X hacia arriba</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Aviso: %1</translation>
    </message>
    <message>
        <source>Boring bar: path of the imaginary tool tip for nose radius %1 mm (tip 2), computed by TolTurn: no G41/G42; set the nose radius to 0 in its tool offsets</source>
        <translation>Barra de mandrinar: trayectoria de la punta teórica de la herramienta para radio de punta %1 mm (punta 2), calculada por TolTurn: sin G41/G42; ponga el radio de punta a 0 en sus correctores</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 2</source>
        <translation>Compensación de radio de punta G41: filo D1 con radio %1 mm, posición de filo 2</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: tool table diameter D%1, orientation Q3</source>
        <translation>Compensación de radio de punta G41: tabla de herramientas diámetro D%1, orientación Q3</translation>
    </message>
    <message>
        <source>G41 nose radius compensation: radius %1 mm and tip 2 in the tool geometry offset</source>
        <translation>Compensación de radio de punta G41: radio %1 mm y punta 2 en el corrector de geometría</translation>
    </message>
    <message>
        <source>Bore pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</source>
        <translation>Pasada de mandrinado %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm</translation>
    </message>
    <message>
        <source>Clear of the part for the tool change: the boring bar&apos;s overhang and the clearance off the end face, above the turning path (or the machine&apos;s own tool-change position)</source>
        <translation>Libre de la pieza para el cambio de herramienta: el voladizo de la barra de mandrinar y la distancia a la cara frontal, por encima de la trayectoria de torneado (o la posición de cambio de la máquina)</translation>
    </message>
</context>
<context>
    <name>ProfileChains</name>
    <message>
        <source>left end face</source>
        <translation>cara extrema izquierda</translation>
    </message>
    <message>
        <source>right end face</source>
        <translation>cara extrema derecha</translation>
    </message>
    <message>
        <source>shoulder</source>
        <translation>resalte</translation>
    </message>
    <message>
        <source>cylinder %1</source>
        <translation>cilindro %1</translation>
    </message>
    <message>
        <source>cone</source>
        <translation>cono</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>chaflán</translation>
    </message>
    <message>
        <source>radius R%1</source>
        <translation>radio R%1</translation>
    </message>
    <message>
        <source>bore bottom</source>
        <translation>fondo del agujero</translation>
    </message>
    <message>
        <source>bore step</source>
        <translation>escalón del agujero</translation>
    </message>
    <message>
        <source>bore %1</source>
        <translation>agujero %1</translation>
    </message>
    <message>
        <source>drill point</source>
        <translation>punta de broca</translation>
    </message>
    <message>
        <source>bore cone</source>
        <translation>cono del agujero</translation>
    </message>
    <message>
        <source>bore chamfer</source>
        <translation>chaflán del agujero</translation>
    </message>
    <message>
        <source>bore radius R%1</source>
        <translation>radio del agujero R%1</translation>
    </message>
    <message>
        <source>the revolved face %1 (from z = %2 mm to z = %3 mm, r = %4 to %5 mm) does not join the outer or inner contour (a closed inner cavity, or faces beyond a gap in the section) and is left out of the profile</source>
        <translation>la cara de revolución %1 (de z = %2 mm a z = %3 mm, r = %4 a %5 mm) no se une al contorno exterior ni al interior (una cavidad interior cerrada, o caras situadas más allá de una interrupción de la sección) y se excluye del perfil</translation>
    </message>
    <message>
        <source>the revolved faces do not form a closed section from the left end (z = %1 mm) to the right end (z = %2 mm): the contour from the left end stops at z = %3 mm, r = %4 mm, where a face is missing or not turned (see the warnings)</source>
        <translation>las caras de revolución no forman una sección cerrada desde el extremo izquierdo (z = %1 mm) hasta el extremo derecho (z = %2 mm): el contorno que parte del extremo izquierdo se interrumpe en z = %3 mm, r = %4 mm, donde falta una cara o hay una que no se tornea (véanse los avisos)</translation>
    </message>
</context>
<context>
    <name>ProfileEditing</name>
    <message>
        <source>the %1 contour has no vertex %2</source>
        <translation>el contorno %1 no tiene el vértice %2</translation>
    </message>
    <message>
        <source>a step is inserted into a cylinder; %1 is not one</source>
        <translation>un escalón se inserta en un cilindro; %1 no lo es</translation>
    </message>
    <message>
        <source>the step of %1 must lie inside it (z %2 … %3 mm), but z is %4 mm</source>
        <translation>el escalón de %1 debe quedar dentro de él (z %2 … %3 mm), pero z es %4 mm</translation>
    </message>
    <message>
        <source>the step&apos;s diameter must differ from Ø%1 mm and be above zero, but is %2 mm</source>
        <translation>el diámetro del escalón debe ser distinto de Ø%1 mm y mayor que cero, pero es %2 mm</translation>
    </message>
    <message>
        <source>step face</source>
        <translation>cara del escalón</translation>
    </message>
    <message>
        <source>step diameter</source>
        <translation>diámetro del escalón</translation>
    </message>
    <message>
        <source>vertex %1 of the %2 contour is not a corner between two features</source>
        <translation>el vértice %1 del contorno %2 no es una esquina entre dos elementos</translation>
    </message>
    <message>
        <source>a corner is broken between a face and a cylinder; %1 and %2 are not</source>
        <translation>una arista se rompe entre una cara y un cilindro; %1 y %2 no lo son</translation>
    </message>
    <message>
        <source>the corner of %1 and %2 takes at most %3 mm, but the size is %4 mm</source>
        <translation>la esquina entre %1 y %2 admite como máximo %3 mm, pero el tamaño es %4 mm</translation>
    </message>
    <message>
        <source>edge round</source>
        <translation>redondeo de arista</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>chaflán</translation>
    </message>
    <message>
        <source>a cone is made from a cylinder; %1 is not one</source>
        <translation>un cono se crea a partir de un cilindro; %1 no lo es</translation>
    </message>
    <message>
        <source>the cone&apos;s end needs a diameter other than Ø%1 mm, but it is %2 mm</source>
        <translation>el final del cono necesita un diámetro distinto de Ø%1 mm, pero es %2 mm</translation>
    </message>
    <message>
        <source>a cylinder is made from a cone; %1 is not one</source>
        <translation>un cilindro se crea a partir de un cono; %1 no lo es</translation>
    </message>
    <message>
        <source>a bore starts at an end face of the part; %1 is not one</source>
        <translation>un agujero empieza en una cara extrema de la pieza; %1 no lo es</translation>
    </message>
    <message>
        <source>a bore needs a depth and a diameter above zero, but they are %1 and %2 mm</source>
        <translation>un agujero necesita una profundidad y un diámetro mayores que cero, pero son %1 y %2 mm</translation>
    </message>
    <message>
        <source>bore</source>
        <translation>agujero</translation>
    </message>
    <message>
        <source>bore bottom</source>
        <translation>fondo del agujero</translation>
    </message>
    <message>
        <source>there is no feature %1</source>
        <translation>no existe el elemento %1</translation>
    </message>
    <message>
        <source>the features beside %1 are parallel: there is no corner to give back</source>
        <translation>los elementos contiguos a %1 son paralelos: no hay ninguna esquina que restituir</translation>
    </message>
    <message>
        <source>only a chamfer or an edge round changes into the other; %1 is neither</source>
        <translation>solo un chaflán o un redondeo de arista se convierte en el otro; %1 no es ninguno de los dos</translation>
    </message>
    <message>
        <source>moving the corner would make %1 turn back along z (an undercut), which needs an undercut insert; move it less, or insert a DIN 509 undercut</source>
        <translation>mover la esquina haría que %1 retrocediera a lo largo de z (una entalla), lo que requiere una plaquita de entallar; desplácela menos, o inserte una entalla DIN 509</translation>
    </message>
    <message>
        <source>the part is bored from this end already (or through); edit its bore instead</source>
        <translation>la pieza ya tiene un agujero desde este extremo (o pasante); edite ese agujero en su lugar</translation>
    </message>
    <message>
        <source>a bore %1 mm deep would meet the bore from the other end, whose bottom is at z = %2 mm: leave solid between them, or make it one through bore</source>
        <translation>un agujero de %1 mm de profundidad se uniría con el agujero del otro extremo, cuyo fondo está en z = %2 mm: deje material macizo entre ambos, o conviértalos en un único agujero pasante</translation>
    </message>
    <message>
        <source>%1 is an end of the %2 contour (or of a bore); move it instead of deleting it</source>
        <translation>%1 es un extremo del contorno %2 (o de un agujero); muévalo en lugar de borrarlo</translation>
    </message>
</context>
<context>
    <name>ProfileValidation</name>
    <message>
        <source>the coordinate is not a finite number</source>
        <translation>la coordenada no es un número finito</translation>
    </message>
    <message>
        <source>must not be negative, but is %1 mm</source>
        <translation>no debe ser negativo, pero es %1 mm</translation>
    </message>
    <message>
        <source>a cylinder keeps one radius, but this one goes from r = %1 mm to r = %2 mm (a cone?)</source>
        <translation>un cilindro mantiene un único radio, pero este va de r = %1 mm a r = %2 mm (¿un cono?)</translation>
    </message>
    <message>
        <source>the cylinder has zero length: it starts and ends at z = %1 mm</source>
        <translation>el cilindro tiene longitud cero: empieza y termina en z = %1 mm</translation>
    </message>
    <message>
        <source>a cylinder needs a radius above zero, but r = %1 mm</source>
        <translation>un cilindro necesita un radio mayor que cero, pero r = %1 mm</translation>
    </message>
    <message>
        <source>a face stays at one z, but this one goes from z = %1 mm to z = %2 mm (a cone?)</source>
        <translation>una cara se mantiene en una única z, pero esta va de z = %1 mm a z = %2 mm (¿un cono?)</translation>
    </message>
    <message>
        <source>the face has zero length: it starts and ends at r = %1 mm</source>
        <translation>la cara tiene longitud cero: empieza y termina en r = %1 mm</translation>
    </message>
    <message>
        <source>a %1 must change radius, but it stays at r = %2 mm (a cylinder?)</source>
        <translation>un segmento %1 debe cambiar de radio, pero se mantiene en r = %2 mm (¿un cilindro?)</translation>
    </message>
    <message>
        <source>the radius must be above zero, but is %1 mm</source>
        <translation>el radio debe ser mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the radius has zero length: both ends are at %1</source>
        <translation>el radio tiene longitud cero: ambos extremos están en %1</translation>
    </message>
    <message>
        <source>a radius of %1 mm cannot join two points %2 mm apart (it needs at least %3 mm)</source>
        <translation>un radio de %1 mm no puede unir dos puntos separados %2 mm (necesita al menos %3 mm)</translation>
    </message>
    <message>
        <source>overlaps %1: it starts at %2, left of where %1 ends, %3</source>
        <translation>se solapa con %1: empieza en %2, a la izquierda de donde termina %1, %3</translation>
    </message>
    <message>
        <source>leaves a gap: it starts at %2, but %1 ends at %3</source>
        <translation>deja un hueco: empieza en %2, pero %1 termina en %3</translation>
    </message>
    <message>
        <source>the face turns back over %1 at z = %2 mm: the two faces overlap</source>
        <translation>la cara retrocede sobre %1 en z = %2 mm: las dos caras se solapan</translation>
    </message>
    <message>
        <source>the outer contour must start at the left end of the part, z = 0 mm, but starts at z = %1 mm</source>
        <translation>el contorno exterior debe empezar en el extremo izquierdo de la pieza, z = 0 mm, pero empieza en z = %1 mm</translation>
    </message>
    <message>
        <source>the part has zero length: the outer contour ends at z = %1 mm</source>
        <translation>la pieza tiene longitud cero: el contorno exterior termina en z = %1 mm</translation>
    </message>
    <message>
        <source>the left end face must start at r = %1 mm (%2), but starts at r = %3 mm</source>
        <translation>la cara extrema izquierda debe empezar en r = %1 mm (%2), pero empieza en r = %3 mm</translation>
    </message>
    <message>
        <source>the bore</source>
        <translation>el agujero</translation>
    </message>
    <message>
        <source>the axis</source>
        <translation>el eje de giro</translation>
    </message>
    <message>
        <source>the right end face must end at r = %1 mm (%2), but ends at r = %3 mm</source>
        <translation>la cara extrema derecha debe terminar en r = %1 mm (%2), pero termina en r = %3 mm</translation>
    </message>
    <message>
        <source>the inner contour must start at the left end (z = 0 mm) or on the axis (r = 0 mm), but starts at %1</source>
        <translation>el contorno interior debe empezar en el extremo izquierdo (z = 0 mm) o en el eje (r = 0 mm), pero empieza en %1</translation>
    </message>
    <message>
        <source>the inner contour must end at the right end (z = %1 mm) or on the axis (r = 0 mm), but ends at %2</source>
        <translation>el contorno interior debe terminar en el extremo derecho (z = %1 mm) o en el eje (r = 0 mm), pero termina en %2</translation>
    </message>
    <message>
        <source>the bore ends at z = %1 mm, beyond the right end of the part at z = %2 mm</source>
        <translation>el agujero termina en z = %1 mm, más allá del extremo derecho de la pieza en z = %2 mm</translation>
    </message>
    <message>
        <source>the bore reaches r = %1 mm at z = %2 mm, where the outer contour is at r = %3 mm: the inner radius meets the outer one</source>
        <translation>el agujero alcanza r = %1 mm en z = %2 mm, donde el contorno exterior está en r = %3 mm: el radio interior llega al exterior</translation>
    </message>
    <message>
        <source>every feature needs an id, but this one is empty</source>
        <translation>cada elemento necesita un id, pero este está vacío</translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used by another feature; ids must be unique</source>
        <translation>el id &apos;%1&apos; ya lo usa otro elemento; los id deben ser únicos</translation>
    </message>
    <message>
        <source>the stock diameter must be above zero, but is %1 mm</source>
        <translation>el diámetro del bruto debe ser mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the outer contour has no segments</source>
        <translation>el contorno exterior no tiene segmentos</translation>
    </message>
    <message>
        <source>the stock diameter %1 mm is smaller than the part, whose largest diameter is %2 mm</source>
        <translation>el diámetro del bruto, %1 mm, es menor que la pieza, cuyo diámetro máximo es %2 mm</translation>
    </message>
    <message>
        <source>the cylinder runs backwards along z, from z = %1 mm to z = %2 mm: a contour runs from left to right, and only an undercut&apos;s cones and radii may go back</source>
        <translation>el cilindro va hacia atrás a lo largo de z, de z = %1 mm a z = %2 mm: un contorno va de izquierda a derecha, y solo los conos y radios de una entalla pueden retroceder</translation>
    </message>
    <message>
        <source>a %1 must move along z, but it starts and ends at z = %2 mm (a face?)</source>
        <translation>un %1 debe avanzar a lo largo de z, pero empieza y termina en z = %2 mm (¿una cara?)</translation>
    </message>
    <message>
        <source>the inner contour leaves the axis a second time at z = %1 mm: a part has at most one bore from each end</source>
        <translation>el contorno interior se separa del eje por segunda vez en z = %1 mm: una pieza tiene como máximo un agujero desde cada extremo</translation>
    </message>
    <message>
        <source>the bores from both ends meet on the axis at z = %1 mm, leaving no solid between them: make them one through bore, stepped by a face from r = %2 mm to r = %3 mm</source>
        <translation>los agujeros de ambos extremos se unen en el eje en z = %1 mm, sin dejar material macizo entre ellos: conviértalos en un único agujero pasante, escalonado por una cara de r = %2 mm a r = %3 mm</translation>
    </message>
    <message>
        <source>the bore from z = %1 mm to z = %2 mm is closed at both ends (a cavity that no tool can reach): it must open at z = 0 mm or at z = %3 mm</source>
        <translation>el agujero de z = %1 mm a z = %2 mm está cerrado por ambos extremos (una cavidad a la que no llega ninguna herramienta): debe abrirse en z = 0 mm o en z = %3 mm</translation>
    </message>
    <message>
        <source>crosses %1 at %2: the contour overlaps itself (an undercut deeper than the material around it?)</source>
        <translation>cruza %1 en %2: el contorno se solapa consigo mismo (¿una entalla más profunda que el material que la rodea?)</translation>
    </message>
</context>
<context>
    <name>ProjectFile</name>
    <message>
        <source>&apos;%1&apos; does not exist</source>
        <translation>&apos;%1&apos; no existe</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a folder, not a project file</source>
        <translation>&apos;%1&apos; es una carpeta, no un archivo de proyecto</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2 MiB, more than the %3 MiB a project file may have</source>
        <translation>&apos;%1&apos; ocupa %2 MiB, más de los %3 MiB que puede ocupar un archivo de proyecto</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>no se puede abrir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not written: the project would not open again (%2)</source>
        <translation>&apos;%1&apos; no se escribió: el proyecto no se podría volver a abrir (%2)</translation>
    </message>
</context>
<context>
    <name>ProjectJson</name>
    <message>
        <source>segment type</source>
        <translation>tipo de segmento</translation>
    </message>
    <message>
        <source>arc direction</source>
        <translation>sentido del arco</translation>
    </message>
    <message>
        <source>expected a segment object, found %1</source>
        <translation>se esperaba un objeto de segmento y se ha encontrado %1</translation>
    </message>
    <message>
        <source>force model</source>
        <translation>modelo de fuerzas</translation>
    </message>
    <message>
        <source>objective</source>
        <translation>objetivo</translation>
    </message>
    <message>
        <source>clamping method</source>
        <translation>método de sujeción</translation>
    </message>
    <message>
        <source>expected an object, found %1</source>
        <translation>se esperaba un objeto y se ha encontrado %1</translation>
    </message>
    <message>
        <source>pass kind</source>
        <translation>tipo de pasada</translation>
    </message>
    <message>
        <source>tolerance type</source>
        <translation>tipo de tolerancia</translation>
    </message>
    <message>
        <source>this is not a TolTurn project: format is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <translation>no es un proyecto de TolTurn: el formato es &quot;%1&quot; y se esperaba &quot;%2&quot;</translation>
    </message>
    <message>
        <source>invalid JSON at line %1, column %2: %3</source>
        <translation>JSON no válido en la línea %1, columna %2: %3</translation>
    </message>
    <message>
        <source>a project file holds one JSON object, not a list</source>
        <translation>un archivo de proyecto contiene un único objeto JSON, no una lista</translation>
    </message>
    <message>
        <source>part end</source>
        <translation>extremo de la pieza</translation>
    </message>
    <message>
        <source>unknown format version %1; this TolTurn reads versions 1 to %2</source>
        <translation>versión de formato desconocida %1; este TolTurn lee las versiones 1 a %2</translation>
    </message>
    <message>
        <source>cut</source>
        <translation>corte</translation>
    </message>
    <message>
        <source>milling direction</source>
        <translation>sentido de fresado</translation>
    </message>
    <message>
        <source>milled tolerance type</source>
        <translation>tipo de tolerancia de fresado</translation>
    </message>
    <message>
        <source>expected three numbers, found %1</source>
        <translation>se esperaban tres números y se ha encontrado %1</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>se esperaba un número y se ha encontrado %1</translation>
    </message>
    <message>
        <source>milled feature kind</source>
        <translation>tipo de elemento fresado</translation>
    </message>
    <message>
        <source>expected %1, found %2</source>
        <translation>se esperaba %1 y se ha encontrado %2</translation>
    </message>
    <message>
        <source>a constraint name</source>
        <translation>un nombre de restricción</translation>
    </message>
    <message>
        <source>a feature id</source>
        <translation>un identificador de elemento</translation>
    </message>
    <message>
        <source>a datum letter</source>
        <translation>una letra de referencia</translation>
    </message>
</context>
<context>
    <name>ProjectValidation</name>
    <message>
        <source>%1 is missing (empty)</source>
        <translation>falta %1 (vacío)</translation>
    </message>
    <message>
        <source>must be zero or more, but is %1 mm</source>
        <translation>debe ser cero o más, pero es %1 mm</translation>
    </message>
    <message>
        <source>a part held in a chuck needs a clamped length above zero, but it is %1 mm</source>
        <translation>una pieza sujeta en un plato necesita una longitud de amarre mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the clamped length %1 mm leaves nothing to turn on a part %2 mm long</source>
        <translation>la longitud de amarre de %1 mm no deja nada que tornear en una pieza de %2 mm de longitud</translation>
    </message>
    <message>
        <source>a part between centres is not clamped; the clamped length %1 mm is ignored</source>
        <translation>una pieza entre puntos no está amarrada; se ignora la longitud de amarre de %1 mm</translation>
    </message>
    <message>
        <source>must be above zero, but is %1</source>
        <translation>debe ser mayor que cero, pero es %1</translation>
    </message>
    <message>
        <source>a datum is named by one or two capital letters (ISO 5459), not &apos;%1&apos;</source>
        <translation>una referencia se designa con una o dos letras mayúsculas (ISO 5459), no &apos;%1&apos;</translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is defined twice</source>
        <translation>la referencia &apos;%1&apos; está definida dos veces</translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation>no existe el elemento &apos;%1&apos; en el perfil</translation>
    </message>
    <message>
        <source>give either an ISO 286 class or both limit deviations (upper_um, lower_um)</source>
        <translation>indique una clase ISO 286 o las dos diferencias límite (upper_um, lower_um)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an ISO 286 tolerance class (a letter and a grade, e.g. h6 or H7)</source>
        <translation>&apos;%1&apos; no es una clase de tolerancia ISO 286 (una letra y un grado, p. ej. h6 o H7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a shaft class, but feature &apos;%2&apos; is a bore: use capital letters (e.g. H7)</source>
        <translation>&apos;%1&apos; es una clase de eje, pero el elemento &apos;%2&apos; es un agujero: use mayúsculas (p. ej. H7)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a hole class, but feature &apos;%2&apos; is an outer surface: use small letters (e.g. h6)</source>
        <translation>&apos;%1&apos; es una clase de agujero, pero el elemento &apos;%2&apos; es una superficie exterior: use minúsculas (p. ej. h6)</translation>
    </message>
    <message>
        <source>both limit deviations are needed, upper_um and lower_um</source>
        <translation>se necesitan las dos diferencias límite, upper_um y lower_um</translation>
    </message>
    <message>
        <source>the upper deviation %1 µm must be above the lower deviation %2 µm</source>
        <translation>la diferencia superior %1 µm debe ser mayor que la diferencia inferior %2 µm</translation>
    </message>
    <message>
        <source>a %1 tolerance needs a zone width above zero, but it is %2</source>
        <translation>una tolerancia %1 necesita una anchura de zona mayor que cero (valor: %2)</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>no indicado</translation>
    </message>
    <message>
        <source>a %1 tolerance is defined relative to a datum, but none is given</source>
        <translation>una tolerancia %1 se define respecto a una referencia, pero no se ha indicado ninguna</translation>
    </message>
    <message>
        <source>datum &apos;%1&apos; is not defined in the project&apos;s datums</source>
        <translation>la referencia &apos;%1&apos; no está definida entre las referencias del proyecto</translation>
    </message>
    <message>
        <source>a %1 tolerance cannot sit on feature &apos;%2&apos;, which is a %3</source>
        <translation>una tolerancia %1 no puede aplicarse al elemento &apos;%2&apos;, que es de tipo %3</translation>
    </message>
    <message>
        <source>a length runs between two faces; there is no feature &apos;%1&apos; in the profile</source>
        <translation>una longitud se mide entre dos caras; no existe el elemento &apos;%1&apos; en el perfil</translation>
    </message>
    <message>
        <source>a length runs between two different faces; &apos;%1&apos; is not one</source>
        <translation>una longitud se mide entre dos caras distintas; &apos;%1&apos; no lo es</translation>
    </message>
    <message>
        <source>every tolerance needs an id, but this one is empty</source>
        <translation>cada tolerancia necesita un id, pero este está vacío</translation>
    </message>
    <message>
        <source>the id &apos;%1&apos; is used twice</source>
        <translation>el id &apos;%1&apos; se usa dos veces</translation>
    </message>
    <message>
        <source>must be zero or more, but is %1</source>
        <translation>debe ser cero o más, pero es %1</translation>
    </message>
    <message>
        <source>the li_du force model needs normal_pressure_MPa (K_n) and friction_ratio (K_f); fit them from measured forces with &apos;tolturn-cli calibrate-forces&apos;</source>
        <translation>el modelo de fuerzas li_du necesita normal_pressure_MPa (K_n) y friction_ratio (K_f); ajústelos a partir de fuerzas medidas con &apos;tolturn-cli calibrate-forces&apos;</translation>
    </message>
    <message>
        <source>where the machine characterisation comes from</source>
        <translation>la procedencia de la caracterización de la máquina</translation>
    </message>
    <message>
        <source>spindle springs need the pivot distance Lc of the k2 spring behind the chuck face</source>
        <translation>los muelles del husillo necesitan la distancia de pivote Lc del muelle k2 detrás de la cara del plato</translation>
    </message>
    <message>
        <source>must be at least the minimum %1, but is %2</source>
        <translation>debe ser al menos el mínimo %1, pero es %2</translation>
    </message>
    <message>
        <source>the Taylor exponent n lies between 0 and 1, but is %1</source>
        <translation>el exponente de Taylor n está entre 0 y 1, pero es %1</translation>
    </message>
    <message>
        <source>the source of the Taylor constants</source>
        <translation>la fuente de las constantes de Taylor</translation>
    </message>
    <message>
        <source>the source of the cutting ranges</source>
        <translation>la fuente de los intervalos de corte</translation>
    </message>
    <message>
        <source>unknown constraint &quot;%1&quot;; the constraints are: %2</source>
        <translation>restricción desconocida &quot;%1&quot;; las restricciones son: %2</translation>
    </message>
    <message>
        <source>the work material</source>
        <translation>el material de la pieza</translation>
    </message>
    <message>
        <source>the machine</source>
        <translation>la máquina</translation>
    </message>
    <message>
        <source>the insert code</source>
        <translation>el código de la plaquita</translation>
    </message>
    <message>
        <source>give both Taylor constants C and n, or neither</source>
        <translation>indique las dos constantes de Taylor C y n, o ninguna</translation>
    </message>
    <message>
        <source>must be above absolute zero (-273.15 °C), but is %1 °C</source>
        <translation>debe estar por encima del cero absoluto (-273,15 °C), pero es %1 °C</translation>
    </message>
    <message>
        <source>the boring bar&apos;s insert code</source>
        <translation>el código de la plaquita de la barra de mandrinar</translation>
    </message>
    <message>
        <source>the boring bar</source>
        <translation>la barra de mandrinar</translation>
    </message>
    <message>
        <source>only a boring bar starts from a pilot hole: give it in boring_tool</source>
        <translation>solo una barra de mandrinar parte de un agujero previo: indíquelo en boring_tool</translation>
    </message>
    <message>
        <source>ISO 286 gives no limits for %1 at Ø%2 mm: %3</source>
        <translation>ISO 286 no da diferencias límite para %1 en Ø%2 mm: %3</translation>
    </message>
    <message>
        <source>not given: the thermal drift is computed for a machine warmed through, the largest drift; give the time since the machine started</source>
        <translation>no indicado: la deriva térmica se calcula para una máquina caliente del todo, la mayor deriva; indique el tiempo desde el arranque de la máquina</translation>
    </message>
    <message>
        <source>not given: taken as the characterisation&apos;s reference temperature, %1 °C, so no drift from it</source>
        <translation>no indicada: se toma la temperatura de referencia de la caracterización, %1 °C, sin deriva por ella</translation>
    </message>
    <message>
        <source>least cost needs the machine and operator rate per minute, but it is 0 (or not given)</source>
        <translation>el coste mínimo necesita la tarifa de máquina y operario por minuto, pero es 0 (o no se indicó)</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 allow no common size: one needs at most %2 µm, another at least %3 µm</source>
        <translation>las tolerancias de tamaño del elemento %1 no permiten un tamaño común: una exige como mucho %2 µm, otra al menos %3 µm</translation>
    </message>
    <message>
        <source>%1 is below %2, the least the program can state; it would be written as zero</source>
        <translation>%1 está por debajo de %2, el menor valor que el programa puede indicar; se escribiría como cero</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 leave a zone of no width (both limits at %2 µm), which no cut can hold</source>
        <translation>las tolerancias dimensionales del elemento %1 dejan una zona sin anchura (ambos límites en %2 µm), que ningún corte puede mantener</translation>
    </message>
    <message>
        <source>the size tolerances of feature %1 leave a zone from %2 to %3 µm, narrower than the 1 µm step of the program&apos;s diameters: no program can aim into it</source>
        <translation>las tolerancias dimensionales del elemento %1 dejan una zona de %2 a %3 µm, más estrecha que el paso de 1 µm de los diámetros del programa: ningún programa puede apuntar a ella</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Datum %1</source>
        <translation>Referencia %1</translation>
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
        <translation>cualquiera</translation>
    </message>
    <message>
        <source>not reachable</source>
        <translation>inalcanzable</translation>
    </message>
    <message>
        <source>passes on any machine in the range</source>
        <translation>cumple en cualquier máquina del rango</translation>
    </message>
    <message>
        <source>passes only if the machine is stiffer than %1 N/µm</source>
        <translation>cumple solo si la máquina es más rígida que %1 N/µm</translation>
    </message>
    <message>
        <source>passes only on the stiffer machines of the range</source>
        <translation>cumple solo en las máquinas más rígidas del rango</translation>
    </message>
    <message>
        <source>chuck not measured: radial stiffness %1–%2 N/µm at the chuck face (%3), results at both ends, verdicts and plans at the compliant end</source>
        <translation>plato no medido: rigidez radial %1–%2 N/µm en la cara del plato (%3), resultados en ambos extremos, veredictos y planes en el extremo flexible</translation>
    </message>
    <message>
        <source>spindle–chuck as measured</source>
        <translation>husillo–plato según lo medido</translation>
    </message>
    <message>
        <source>chuck neither measured nor published: taken as rigid (optimistic)</source>
        <translation>plato ni medido ni publicado: se toma como rígido (optimista)</translation>
    </message>
    <message>
        <source>tailstock and centres not measured and no published stiffness: taken as rigid (optimistic); see the stiffness each tolerance needs</source>
        <translation>contrapunto y puntos no medidos y sin rigidez publicada: se toman como rígidos (optimista); vea la rigidez que necesita cada tolerancia</translation>
    </message>
    <message>
        <source>%1–%2 N/µm only</source>
        <translation>solo %1–%2 N/µm</translation>
    </message>
    <message>
        <source>passes on the compliant machines of the range, not on the stiffest</source>
        <translation>cumple en las máquinas flexibles del rango, no en la más rígida</translation>
    </message>
    <message>
        <source>tailstock as measured</source>
        <translation>contrapunto según lo medido</translation>
    </message>
    <message>
        <source>headstock centre not measured and no published stiffness: taken as rigid (optimistic)</source>
        <translation>punto del cabezal no medido y sin rigidez publicada: se toma como rígido (optimista)</translation>
    </message>
    <message>
        <source>thermal drift not measured: taken as zero (optimistic)</source>
        <translation>deriva térmica no medida: se toma como cero (optimista)</translation>
    </message>
    <message>
        <source>spans set-ups: its error from clamping the part again (where it sits axially in the other set-up) is not known and not in this verdict. </source>
        <translation>abarca montajes: su error por volver a sujetar la pieza (dónde se asienta axialmente en el otro montaje) no se conoce y no está en este veredicto. </translation>
    </message>
    <message>
        <source>collet not measured and no published stiffness: taken as rigid (optimistic); see the stiffness each tolerance needs</source>
        <translation>pinza no medida y sin rigidez publicada: tomada como rígida (optimista); vea la rigidez que necesita cada tolerancia</translation>
    </message>
    <message>
        <source>fails as programmed; an offset of %1 µm on the diameter holds it on any machine in the range</source>
        <translation>no cumple tal como está programado; una corrección de %1 µm en el diámetro la mantiene en cualquier máquina del rango</translation>
    </message>
    <message>
        <source>fails as programmed even on the stiffest machine of the range</source>
        <translation>no cumple tal como está programado ni en la máquina más rígida del rango</translation>
    </message>
    <message>
        <source>%1; an offset of %2 µm on the diameter holds it on any machine in the range</source>
        <translation>%1; una corrección de %2 µm en el diámetro la mantiene en cualquier máquina del rango</translation>
    </message>
    <message>
        <source>not finished by the program: %1</source>
        <translation>no terminado por el programa: %1</translation>
    </message>
</context>
<context>
    <name>Remedies</name>
    <message>
        <source>, below the speed range, which starts at %1 m/min; at that speed it needs an insert grade with C of at least %2 m/min.</source>
        <translation>, por debajo del rango de velocidad, que empieza en %1 m/min; a esa velocidad requiere una calidad de plaquita con C de al menos %2 m/min.</translation>
    </message>
    <message>
        <source>%1 (%2 mm)</source>
        <translation>%1 (%2 mm)</translation>
    </message>
    <message>
        <source>%1 ≤ %2 µm needs a feed of at most %3 mm/rev with the nose radius of %4</source>
        <translation>%1 ≤ %2 µm requiere un avance de como máximo %3 mm/rev con el radio de punta de %4</translation>
    </message>
    <message>
        <source>, below the feed range, which starts at %1 mm/rev; at that feed it needs a nose radius of at least %2 mm on %3.</source>
        <translation>, por debajo del rango de avance, que empieza en %1 mm/rev; con ese avance requiere un radio de punta de al menos %2 mm en %3.</translation>
    </message>
    <message>
        <source>A tool life of %1 min needs a cutting speed of at most %2 m/min (Taylor C = %3 m/min, n = %4)</source>
        <translation>Una vida de herramienta de %1 min requiere una velocidad de corte de como máximo %2 m/min (Taylor C = %3 m/min, n = %4)</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>Tolerance report: %1</source>
        <translation>Informe de tolerancias: %1</translation>
    </message>
    <message>
        <source>1  Part</source>
        <translation>1  Pieza</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Dato</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Insert</source>
        <translation>Plaquita</translation>
    </message>
    <message>
        <source>%1: %2° corner, nose radius %3 mm</source>
        <translation>%1: ángulo de punta %2°, radio de punta %3 mm</translation>
    </message>
    <message>
        <source>Holder</source>
        <translation>Portaherramientas</translation>
    </message>
    <message>
        <source>%1: entering angle %2°</source>
        <translation>%1: ángulo de posición %2°</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Sujeción</translation>
    </message>
    <message>
        <source>%1, clamped length %2 mm</source>
        <translation>%1, longitud de amarre %2 mm</translation>
    </message>
    <message>
        <source>Force model</source>
        <translation>Modelo de fuerzas</translation>
    </message>
    <message>
        <source>Machine characterisation</source>
        <translation>Caracterización de la máquina</translation>
    </message>
    <message>
        <source>3  Predicted deviation</source>
        <translation>3  Desviación prevista</translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [mm]</source>
        <translation>z desde el extremo izquierdo de la pieza [mm]</translation>
    </message>
    <message>
        <source>deviation [µm]</source>
        <translation>desviación [µm]</translation>
    </message>
    <message>
        <source>Radial deviation of the outer contour (material left)</source>
        <translation>Desviación radial del contorno exterior (material sobrante)</translation>
    </message>
    <message>
        <source>Radial deviation of the bores (material left)</source>
        <translation>Desviación radial de los agujeros (material sobrante)</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Cara</translation>
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
        <translation>oscilación axial e [µm]</translation>
    </message>
    <message>
        <source>4  Tolerances</source>
        <translation>4  Tolerancias</translation>
    </message>
    <message>
        <source>The project has no tolerances.</source>
        <translation>El proyecto no tiene tolerancias.</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Característica</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Especificación</translation>
    </message>
    <message>
        <source>Value [µm]</source>
        <translation>Valor [µm]</translation>
    </message>
    <message>
        <source>Limit [µm]</source>
        <translation>Límite [µm]</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>Uso</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <source>optimum</source>
        <translation>óptimo</translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation>avance f [mm/rev]</translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation>velocidad de corte vc [m/min]</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass (green: feasible)</source>
        <translation>Ventana de corte de la pasada de acabado (verde: factible)</translation>
    </message>
    <message>
        <source>5  Plan</source>
        <translation>5  Plan</translation>
    </message>
    <message>
        <source>The project has no planning data (the insert&apos;s cutting ranges), so no plan was optimised.</source>
        <translation>El proyecto no tiene datos de planificación (los intervalos de corte de la plaquita), por lo que no se ha optimizado ningún plan.</translation>
    </message>
    <message>
        <source>Optimal plan (%1): </source>
        <translation>Plan óptimo (%1): </translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one (%1): </source>
        <translation>Ningún plan cumple todas las restricciones; el que menos las incumple (%1): </translation>
    </message>
    <message>
        <source>Binding: %1.</source>
        <translation>Restricciones activas: %1.</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>Posición</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Acción</translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation>Corrección Ø [µm]</translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation>Residuo antes [µm]</translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation>Residuo después [µm]</translation>
    </message>
    <message>
        <source>Compensation of the project&apos;s finishing pass, only where a tolerance needs it:</source>
        <translation>Compensación de la pasada de acabado del proyecto, solo donde lo requiere una tolerancia:</translation>
    </message>
    <message>
        <source>Material data (%1): %2</source>
        <translation>Datos del material (%1): %2</translation>
    </message>
    <message>
        <source>Elastic constants: %1</source>
        <translation>Constantes elásticas: %1</translation>
    </message>
    <message>
        <source>Cutting ranges: %1</source>
        <translation>Intervalos de corte: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>TolTurn report: %1</source>
        <translation>Informe de TolTurn: %1</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>página %1 de %2</translation>
    </message>
    <message>
        <source>Machine: %1.</source>
        <translation>Máquina: %1.</translation>
    </message>
    <message>
        <source>Verdicts</source>
        <translation>Veredictos</translation>
    </message>
    <message>
        <source>On the machine range</source>
        <translation>En el rango de máquinas</translation>
    </message>
    <message>
        <source>Stiffness needed</source>
        <translation>Rigidez necesaria</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>not measured: see the machine assumption on page 1</source>
        <translation>no medida: vea la hipótesis de máquina en la página 1</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Pieza</translation>
    </message>
    <message>
        <source>Drawing no.</source>
        <translation>N.º de plano</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revisión</translation>
    </message>
    <message>
        <source>Planner</source>
        <translation>Planificador</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Fecha</translation>
    </message>
    <message>
        <source>Approved (name, date)</source>
        <translation>Aprobado (nombre, fecha)</translation>
    </message>
    <message>
        <source>Project %1 · written %2 · TolTurn %3 · length %4 mm, stock Ø%5 mm</source>
        <translation>Proyecto %1 · escrito %2 · TolTurn %3 · longitud %4 mm, material en bruto Ø%5 mm</translation>
    </message>
    <message>
        <source>2  Set-up sheet and inputs</source>
        <translation>2  Hoja de preparación y datos</translation>
    </message>
    <message>
        <source>programmed</source>
        <translation>programado</translation>
    </message>
    <message>
        <source>The programmed finishing pass (f %1 mm/rev, vc %2 m/min) lies outside this window.</source>
        <translation>La pasada de acabado programada (f %1 mm/rev, vc %2 m/min) queda fuera de esta ventana.</translation>
    </message>
    <message>
        <source> (Valiño et al. 2008, %1)</source>
        <translation> (Valiño et al. 2008, %1)</translation>
    </message>
    <message>
        <source>size within %1–%2 mm</source>
        <translation>medida entre %1 y %2 mm</translation>
    </message>
    <message>
        <source>%1 of %2 µm predicted against a zone of %3 µm</source>
        <translation>%1 de %2 µm prevista frente a una zona de %3 µm</translation>
    </message>
    <message>
        <source>6  Assumptions</source>
        <translation>6  Hipótesis</translation>
    </message>
    <message>
        <source>What this prediction rests on, beyond the project&apos;s own values:</source>
        <translation>En qué se basa esta predicción, además de los valores del proyecto:</translation>
    </message>
    <message>
        <source>Appendix A  Literature</source>
        <translation>Anexo A  Bibliografía</translation>
    </message>
    <message>
        <source>[1] G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos: Machining error predictive model in a CAPP system for turning: formulation and initial tests (2008). Used: eq. 2–8 (deviation), §III (spindle–chuck springs from a test bar), §V and Fig. 4 (tolerances), §VI (optimisation).</source>
        <translation>[1] G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos: Machining error predictive model in a CAPP system for turning: formulation and initial tests (2008). Se usa: ec. 2–8 (desviación), §III (muelles de husillo y plato a partir de una barra de prueba), §V y fig. 4 (tolerancias), §VI (optimización).</translation>
    </message>
    <message>
        <source>[2] X. Li, R. Du: Analysis and compensation of workpiece errors in turning. Int. J. Prod. Res. 40(7) (2002). Used: eq. 15–20 (forces with the nose radius), §3.4 (compensation).</source>
        <translation>[2] X. Li, R. Du: Analysis and compensation of workpiece errors in turning. Int. J. Prod. Res. 40(7) (2002). Se usa: ec. 15–20 (fuerzas con el radio de punta), §3.4 (compensación).</translation>
    </message>
    <message>
        <source>[3] O. Kienzle: Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und Werkzeugmaschinen. VDI-Z 94 (1952) 299–305. Used: the specific cutting force kc1.1 · h^-mc.</source>
        <translation>[3] O. Kienzle: Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und Werkzeugmaschinen. VDI-Z 94 (1952) 299–305. Se usa: la fuerza específica de corte kc1.1 · h^-mc.</translation>
    </message>
    <message>
        <source>[4] G. R. Cowper: The shear coefficient in Timoshenko&apos;s beam theory. J. Appl. Mech. 33 (1966) 335–340. Used: the shear coefficient of solid and hollow round sections.</source>
        <translation>[4] G. R. Cowper: The shear coefficient in Timoshenko&apos;s beam theory. J. Appl. Mech. 33 (1966) 335–340. Se usa: el coeficiente de cortante de secciones circulares macizas y huecas.</translation>
    </message>
    <message>
        <source>[5] ISO 286-1 and ISO 286-2: limits and fits (tolerance grades, fundamental deviations).</source>
        <translation>[5] ISO 286-1 e ISO 286-2: límites y ajustes (grados de tolerancia, diferencias fundamentales).</translation>
    </message>
    <message>
        <source>[6] ISO 1101: geometrical tolerancing (form, orientation, location and run-out).</source>
        <translation>[6] ISO 1101: tolerancias geométricas (forma, orientación, posición y alabeo).</translation>
    </message>
    <message>
        <source>[7] ISO 3002-1: basic quantities in cutting (entering and trailing edge angles).</source>
        <translation>[7] ISO 3002-1: magnitudes básicas del corte (ángulos de posición principal y secundario).</translation>
    </message>
    <message>
        <source>The equations as implemented, the corrections of printing errors and the validation against closed forms: docs/model.md of TolTurn.</source>
        <translation>Las ecuaciones tal como se implementan, las correcciones de erratas y la validación frente a soluciones cerradas: docs/model.md de TolTurn.</translation>
    </message>
    <message>
        <source>Appendix B  Sources of the data</source>
        <translation>Anexo B  Fuentes de los datos</translation>
    </message>
    <message>
        <source>Chuck stiffness range: %1</source>
        <translation>Intervalo de rigidez del plato: %1</translation>
    </message>
    <message>
        <source>Machine stiffness, measured: %1</source>
        <translation>Rigidez de la máquina, medida: %1</translation>
    </message>
    <message>
        <source>Tool life: %1</source>
        <translation>Vida de la herramienta: %1</translation>
    </message>
    <message>
        <source>z from the held (right) end [mm]</source>
        <translation>z desde el extremo sujetado (derecho) [mm]</translation>
    </message>
    <message>
        <source>Feed [mm/rev]</source>
        <translation>Avance [mm/rev]</translation>
    </message>
    <message>
        <source>Limited by</source>
        <translation>Limitado por</translation>
    </message>
    <message>
        <source>kept: %1 is not held at any feed of the range</source>
        <translation>conservado: %1 no se cumple con ningún avance del rango</translation>
    </message>
    <message>
        <source>[8] F. Čuš, U. Župerl: Control strategy for assuring constant surface finish by controlling cutting forces (University of Maribor, 2013). Used: eq. 1 (feed drive), §2 (20 ms constant-force loop with feed override); TolTurn&apos;s feed schedule holds the tolerances feature by feature.</source>
        <translation>[8] F. Čuš, U. Župerl: Control strategy for assuring constant surface finish by controlling cutting forces (Universidad de Maribor, 2013). Usado: ec. 1 (accionamiento de avance), §2 (lazo de fuerza constante cada 20 ms con override de avance); el programa de avances de TolTurn mantiene las tolerancias elemento por elemento.</translation>
    </message>
    <message>
        <source>7  Assumptions</source>
        <translation>7  Hipótesis</translation>
    </message>
    <message>
        <source>[9] E. Öztürk, E. Budak: 5-Eksen Frezelemede Kuvvet ve Şekil Hatalarının Modellenmesi (modelling the forces and form errors of 5-axis milling; in Turkish), Sabancı University. Used: eq. 1–11 (the forces of a ball-end mill at a lead and tilt), table 3 and §4 (the tool&apos;s deflection and the surface-normal error); the milled features&apos; equations as implemented: docs/milling.md.</source>
        <translation>[9] E. Öztürk, E. Budak: 5-Eksen Frezelemede Kuvvet ve Şekil Hatalarının Modellenmesi (modelado de las fuerzas y los errores de forma del fresado en 5 ejes; en turco), Sabancı University. Se usa: ec. 1–11 (las fuerzas de una fresa de punta esférica con un lead y un tilt), tabla 3 y §4 (la flexión de la herramienta y el error normal a la superficie); las ecuaciones de los elementos fresados tal como se implementan: docs/milling.md.</translation>
    </message>
    <message>
        <source>6  Milled features</source>
        <translation>6  Elementos fresados</translation>
    </message>
    <message>
        <source>%1 violated %2</source>
        <translation>%1: incumplida %2</translation>
    </message>
    <message>
        <source>To meet it: %1</source>
        <translation>Para cumplirla: %1</translation>
    </message>
    <message>
        <source>Finishing pass %1, turning insert (nose radius %2 mm): forces (%3) Fc %4 N, Ff %5 N, Fp %6 N; theoretical Ra %7 µm, Rz %8 µm.</source>
        <translation>Pasada de acabado %1, plaquita de torneado (radio de punta %2 mm): fuerzas (%3) Fc %4 N, Ff %5 N, Fp %6 N; rugosidad teórica Ra %7 µm, Rz %8 µm.</translation>
    </message>
    <message>
        <source>Bores, boring bar %1 (nose radius %2 mm), same pass: forces Fc %3 N, Ff %4 N, Fp %5 N; theoretical Ra %6 µm, Rz %7 µm.</source>
        <translation>Agujeros, barra de mandrinar %1 (radio de punta %2 mm), misma pasada: fuerzas Fc %3 N, Ff %4 N, Fp %5 N; rugosidad teórica Ra %6 µm, Rz %7 µm.</translation>
    </message>
    <message>
        <source>Feed schedule of the finishing pass (after Čuš and Župerl [8]): each feature at the largest feed of the range that holds its tolerances and the pass&apos;s limits; %1 s at the programmed %2 mm/rev, %3 s scheduled (%4 %). Programmed only on request (gcode --feed-schedule, the G-code tab).</source>
        <translation>Programa de avances de la pasada de acabado (según Čuš y Župerl [8]): cada elemento con el mayor avance del rango que mantiene sus tolerancias y los límites de la pasada; %1 s con el avance programado de %2 mm/rev, %3 s según el programa (%4 %). Solo se programa si se pide (gcode --feed-schedule, pestaña Código G).</translation>
    </message>
    <message>
        <source>%1 min per part; finishing vc %2 m/min, f %3 mm/rev, ap %4 mm; </source>
        <translation>%1 min por pieza; acabado vc %2 m/min, f %3 mm/rev, ap %4 mm; </translation>
    </message>
    <message numerus="yes">
        <source>%n roughing pass(es) at vc %1 m/min, f %2 mm/rev.</source>
        <translation>
            <numerusform>%n pasada de desbaste a vc %1 m/min, f %2 mm/rev.</numerusform>
            <numerusform>%n pasadas de desbaste a vc %1 m/min, f %2 mm/rev.</numerusform>
        </translation>
    </message>
    <message>
        <source>no roughing: the finishing pass takes the whole stock.</source>
        <translation>sin desbaste: la pasada de acabado quita todo el sobrematerial.</translation>
    </message>
    <message>
        <source>; predicted %1 mm</source>
        <translation>; previsto %1 mm</translation>
    </message>
</context>
<context>
    <name>RevolvedFaces</name>
    <message>
        <source>a plane not perpendicular to the axis (a flat or a side of a keyway)</source>
        <translation>un plano no perpendicular al eje (un plano o un flanco de un chavetero)</translation>
    </message>
    <message>
        <source>a cylinder parallel to the axis but off it (an eccentric or an off-centre hole)</source>
        <translation>un cilindro paralelo al eje pero desplazado de él (una excéntrica o un agujero descentrado)</translation>
    </message>
    <message>
        <source>a cylinder across the axis (a cross hole)</source>
        <translation>un cilindro transversal al eje (un agujero transversal)</translation>
    </message>
    <message>
        <source>a cone whose axis is not the part axis (a countersink of a cross hole)</source>
        <translation>un cono cuyo eje no es el eje de la pieza (el avellanado de un agujero transversal)</translation>
    </message>
    <message>
        <source>a torus whose axis is not the part axis</source>
        <translation>un toro cuyo eje no es el eje de la pieza</translation>
    </message>
    <message>
        <source>a sphere whose centre is off the axis</source>
        <translation>una esfera cuyo centro está fuera del eje</translation>
    </message>
    <message>
        <source>a free-form (B-spline) surface, such as a modelled thread or an engraving</source>
        <translation>una superficie de forma libre (B-spline), como una rosca modelada o un grabado</translation>
    </message>
    <message>
        <source>a surface of revolution of a free-form curve</source>
        <translation>una superficie de revolución de una curva de forma libre</translation>
    </message>
    <message>
        <source>an extruded free-form surface</source>
        <translation>una superficie de forma libre extruida</translation>
    </message>
    <message>
        <source>a surface of a kind TolTurn does not turn (offset or other)</source>
        <translation>una superficie de un tipo que TolTurn no tornea (desplazada u otro)</translation>
    </message>
    <message>
        <source>a part of a turned surface that does not go round (the end wall of a keyway or a slot)</source>
        <translation>una parte de una superficie torneada que no da la vuelta completa (la pared final de un chavetero o de una ranura)</translation>
    </message>
    <message>
        <source>a plane</source>
        <translation>un plano</translation>
    </message>
    <message>
        <source>a cylinder</source>
        <translation>un cilindro</translation>
    </message>
    <message>
        <source>a cone</source>
        <translation>un cono</translation>
    </message>
    <message>
        <source>a sphere</source>
        <translation>una esfera</translation>
    </message>
    <message>
        <source>a torus</source>
        <translation>un toro</translation>
    </message>
    <message>
        <source>a torus about the part axis</source>
        <translation>un toro alrededor del eje de la pieza</translation>
    </message>
    <message>
        <source>a cylinder, cone or face about the part axis</source>
        <translation>un cilindro, cono o cara alrededor del eje de la pieza</translation>
    </message>
</context>
<context>
    <name>SetupPrediction</name>
    <message>
        <source>%1 (set-up %2 of %3, the %4 end held): </source>
        <translation>%1 (montaje %2 de %3, extremo %4 sujetado): </translation>
    </message>
    <message>
        <source>%1. Without it: %2</source>
        <translation>%1. Sin él: %2</translation>
    </message>
</context>
<context>
    <name>SetupSheet</name>
    <message>
        <source>cutting speed</source>
        <translation>velocidad de corte</translation>
    </message>
    <message>
        <source>feed</source>
        <translation>avance</translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation>profundidad de corte</translation>
    </message>
    <message>
        <source>tool overhang</source>
        <translation>voladizo de la herramienta</translation>
    </message>
    <message>
        <source>clamped length</source>
        <translation>longitud sujeta</translation>
    </message>
    <message>
        <source>stock diameter</source>
        <translation>diámetro del material en bruto</translation>
    </message>
    <message>
        <source>chuck: %1 mm in the jaws</source>
        <translation>plato: %1 mm en las garras</translation>
    </message>
    <message>
        <source>centre and driver</source>
        <translation>punto y arrastrador</translation>
    </message>
    <message>
        <source>tailstock centre</source>
        <translation>punto del contrapunto</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>punto</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Pasada</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>n [rpm]</source>
        <translation>n [rpm]</translation>
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
        <source>Power [kW]</source>
        <translation>Potencia [kW]</translation>
    </message>
    <message>
        <source>Time [min]</source>
        <translation>Tiempo [min]</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>total cutting</source>
        <translation>corte total</translation>
    </message>
    <message>
        <source>Program warning: %1</source>
        <translation>Aviso del programa: %1</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Aviso</translation>
    </message>
    <message>
        <source>pass %1</source>
        <translation>pasada %1</translation>
    </message>
    <message>
        <source>passes %1</source>
        <translation>pasadas %1</translation>
    </message>
    <message>
        <source>collet: %1 mm held</source>
        <translation>pinza: %1 mm sujetos</translation>
    </message>
    <message numerus="yes">
        <source>Program %1 for %2, %n pass(es); spindle limit %3 rpm (%4). Checksum (SHA-256, first 16 digits) of the nominal program %5, of the compensated program %6: compare them with `tolturn-cli gcode` or the G-code tab before running.</source>
        <translation>
            <numerusform>Programa %1 para %2, %n pasada; límite del husillo %3 rpm (%4). Suma de control (SHA-256, primeros 16 dígitos) del programa nominal %5, del programa compensado %6: compárelas con `tolturn-cli gcode` o la pestaña G-code antes de ejecutar.</numerusform>
            <numerusform>Programa %1 para %2, %n pasadas; límite del husillo %3 rpm (%4). Suma de control (SHA-256, primeros 16 dígitos) del programa nominal %5, del programa compensado %6: compárelas con `tolturn-cli gcode` o la pestaña G-code antes de ejecutar.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SolidCheck</name>
    <message>
        <source>the solid check was cancelled; the project is unchanged</source>
        <translation>la comprobación con el sólido se ha cancelado; el proyecto no ha cambiado</translation>
    </message>
    <message>
        <source>could not write the mesh script in %1</source>
        <translation>no se ha podido escribir el script de mallado en %1</translation>
    </message>
    <message>
        <source>meshing with gmsh</source>
        <translation>mallando con gmsh</translation>
    </message>
    <message>
        <source>gmsh could not mesh the part with elements of %1 mm (exit code %2): %3</source>
        <translation>gmsh no ha podido mallar la pieza con elementos de %1 mm (código de salida %2): %3</translation>
    </message>
    <message>
        <source>could not write the CalculiX input in %1</source>
        <translation>no se ha podido escribir la entrada de CalculiX en %1</translation>
    </message>
    <message>
        <source>solving with CalculiX: load case %1 of %2</source>
        <translation>resolviendo con CalculiX: caso de carga %1 de %2</translation>
    </message>
    <message>
        <source>it wrote no results</source>
        <translation>no escribió ningún resultado</translation>
    </message>
    <message>
        <source>CalculiX failed (exit code %1): %2</source>
        <translation>CalculiX ha fallado (código de salida %1): %2</translation>
    </message>
    <message>
        <source>CalculiX moved the part by %1 mm, more than its length: the clamping does not hold the solid</source>
        <translation>CalculiX ha desplazado la pieza %1 mm, más que su longitud: la sujeción no retiene el sólido</translation>
    </message>
    <message>
        <source>The machine&apos;s supports are rigid in both models: the check is of the part&apos;s own deflection.</source>
        <translation>Los apoyos de la máquina son rígidos en ambos modelos: se comprueba la deflexión propia de la pieza.</translation>
    </message>
    <message>
        <source>Solid: quadratic tetrahedra (C3D10) of at most %1 mm; %2 nodes, %3 free degrees of freedom.</source>
        <translation>Sólido: tetraedros cuadráticos (C3D10) de como mucho %1 mm; %2 nodos, %3 grados de libertad libres.</translation>
    </message>
    <message>
        <source>The force is a uniform traction on a %1 mm square patch of the turned surface; the solid&apos;s deflection is the area mean of the displacement of its section under the load.</source>
        <translation>La fuerza es una carga superficial uniforme sobre una zona cuadrada de %1 mm de la superficie torneada; la deflexión del sólido es la media sobre el área del desplazamiento de su sección bajo la carga.</translation>
    </message>
    <message>
        <source>A centre holds the end face within 3.35 mm of the axis (DIN 332-1 form A, d2 = 6.7 mm), or 1.78 mm of a bore&apos;s edge.</source>
        <translation>Un punto sujeta la cara frontal a menos de 3,35 mm del eje (DIN 332-1 forma A, d2 = 6,7 mm), o a menos de 1,78 mm del borde de un agujero.</translation>
    </message>
    <message>
        <source>A chuck or collet holds the turned surface of its clamped length rigidly.</source>
        <translation>Un plato o una pinza sujeta rígidamente la superficie torneada de su longitud de sujeción.</translation>
    </message>
    <message>
        <source>The part is checked as finished: stock a later set-up removes is not in either model.</source>
        <translation>La pieza se comprueba acabada: el material que retira un montaje posterior no está en ninguno de los dos modelos.</translation>
    </message>
    <message>
        <source>operation %1 does not exist; the project has %2</source>
        <translation>la operación %1 no existe; el proyecto tiene %2</translation>
    </message>
    <message>
        <source>the mesh size must be a positive length in mm, not %1</source>
        <translation>el tamaño de malla debe ser una longitud positiva en mm, no %1</translation>
    </message>
    <message>
        <source>could not make a temporary folder: %1</source>
        <translation>no se ha podido crear una carpeta temporal: %1</translation>
    </message>
    <message>
        <source>Files kept in %1 (TOLTURN_FE_KEEP).</source>
        <translation>Archivos conservados en %1 (TOLTURN_FE_KEEP).</translation>
    </message>
    <message>
        <source>writing the solid</source>
        <translation>escribiendo el sólido</translation>
    </message>
    <message>
        <source>setting up the load cases</source>
        <translation>preparando los casos de carga</translation>
    </message>
    <message>
        <source>no turned cylinder or cone between the supports is long enough to load</source>
        <translation>ningún cilindro o cono torneado entre los apoyos es lo bastante largo para cargarlo</translation>
    </message>
    <message>
        <source>done</source>
        <translation>terminado</translation>
    </message>
    <message>
        <source>The beam carries its corrections from solid FE (the root in the jaws, a hinge at each shoulder); Timoshenko is the beam without them (docs/solid-fe.md).</source>
        <translation>La viga lleva sus correcciones de EF sólidos (el empotramiento en las garras, una articulación en cada resalte); Timoshenko es la viga sin ellas (docs/solid-fe.md).</translation>
    </message>
    <message>
        <source>The beam is plain Timoshenko, without its corrections.</source>
        <translation>La viga es Timoshenko sin más, sin sus correcciones.</translation>
    </message>
</context>
<context>
    <name>SpindleCalibration</name>
    <message>
        <source>the %1 fit gives %2 = %3, which is not a spring (it must be above zero): the measured deviation does not grow from the chuck as a spindle–chuck held by springs would. Check the measurement, the forces, Lc and that the bar is held in the chuck only</source>
        <translation>el ajuste %1 da %2 = %3, que no es un muelle (debe ser mayor que cero): la desviación medida no crece desde el plato como lo haría un conjunto husillo–plato sujeto por muelles. Revise la medición, las fuerzas, Lc y que la barra esté sujeta solo en el plato</translation>
    </message>
    <message>
        <source>the test bar must be held in the chuck only (Valiño et al. 2008 §III); a centre would carry part of the load</source>
        <translation>la barra de prueba debe sujetarse solo en el plato (Valiño et al. 2008 §III); un punto llevaría parte de la carga</translation>
    </message>
    <message>
        <source>Lc, the distance of the spindle bearing behind the chuck face, must be above zero, but is %1 mm</source>
        <translation>Lc, la distancia del rodamiento del husillo detrás de la cara del plato, debe ser mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the fit of a z² + b z + c needs points at three or more positions z, but there are %1</source>
        <translation>el ajuste de a z² + b z + c necesita puntos en tres o más posiciones z, pero hay %1</translation>
    </message>
    <message>
        <source>z = %1 mm is not on the turned outer surface of the bar</source>
        <translation>z = %1 mm no está en la superficie exterior torneada de la barra</translation>
    </message>
    <message>
        <source>z = %1 mm lies on Ø%2 mm, but the first point on Ø%3 mm: the fit needs the bar&apos;s points on one diameter</source>
        <translation>z = %1 mm está en Ø%2 mm, pero el primer punto en Ø%3 mm: el ajuste necesita los puntos de la barra en un solo diámetro</translation>
    </message>
    <message>
        <source>the radial force must be above zero, but is %1 N</source>
        <translation>la fuerza radial debe ser mayor que cero, pero es %1 N</translation>
    </message>
    <message>
        <source>the bar&apos;s own bending and the toolpost make %1 % of the deviation measured at z = %2 mm: a stiffer (shorter, thicker) bar gives a surer fit</source>
        <translation>la flexión propia de la barra y el portaherramientas suponen el %1 % de la desviación medida en z = %2 mm: una barra más rígida (más corta, más gruesa) da un ajuste más seguro</translation>
    </message>
    <message>
        <source>radial</source>
        <translation>radial</translation>
    </message>
    <message>
        <source>tangential</source>
        <translation>tangencial</translation>
    </message>
    <message>
        <source>tangential_um is given at %1 positions z; the fit needs three or more: the tangential springs are not fitted</source>
        <translation>tangential_um se da en %1 posiciones z; el ajuste necesita tres o más: los muelles tangenciales no se ajustan</translation>
    </message>
    <message>
        <source>the tangential force is %1 N: the tangential springs are not fitted</source>
        <translation>la fuerza tangencial es %1 N: los muelles tangenciales no se ajustan</translation>
    </message>
    <message>
        <source>the tangential springs were fitted for Lc = %1 mm and do not hold at Lc = %2 mm: removed; measure the tangential deviation to fit them again</source>
        <translation>los muelles tangenciales se ajustaron para Lc = %1 mm y no valen para Lc = %2 mm: eliminados; mida la desviación tangencial para ajustarlos de nuevo</translation>
    </message>
    <message>
        <source>three positions z fit a z² + b z + c exactly: the RMS residual of 0 says nothing of the measurement&apos;s scatter, which goes into the springs whole; measure at four or more</source>
        <translation>tres posiciones z se ajustan exactamente a a z² + b z + c: el residuo RMS de 0 no dice nada de la dispersión de la medición, que pasa entera a los muelles; mida en cuatro o más</translation>
    </message>
</context>
<context>
    <name>StepExport</name>
    <message>
        <source>cannot write &apos;%1&apos;: the profile has errors, first %2</source>
        <translation>no se puede escribir &apos;%1&apos;: el perfil tiene errores; el primero: %2</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>no se puede escribir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>OpenCascade could not write the solid to &apos;%1&apos;</source>
        <translation>OpenCascade no ha podido escribir el cuerpo en &apos;%1&apos;</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: renaming the temporary file failed</source>
        <translation>no se puede guardar &apos;%1&apos;: no se ha podido cambiar el nombre del archivo temporal</translation>
    </message>
    <message>
        <source>OpenCascade failed while writing &apos;%1&apos;: %2</source>
        <translation>OpenCascade ha fallado al escribir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>writing &apos;%1&apos; failed: %2</source>
        <translation>error al escribir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>cannot set the permissions of &apos;%1&apos;: %2</source>
        <translation>no se pueden fijar los permisos de &apos;%1&apos;: %2</translation>
    </message>
</context>
<context>
    <name>StepImport</name>
    <message>
        <source>&apos;%1&apos; is not a STEP file: it does not begin with &apos;ISO-10303-21;&apos; (ISO 10303-21)</source>
        <translation>&apos;%1&apos; no es un archivo STEP: no empieza por &apos;ISO-10303-21;&apos; (ISO 10303-21)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is truncated: a STEP file ends with &apos;END-ISO-10303-21;&apos;, which is missing</source>
        <translation>&apos;%1&apos; está truncado: un archivo STEP termina con &apos;END-ISO-10303-21;&apos;, que falta</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an IGES file: its first line is not a Start section record (IGES 5.3)</source>
        <translation>&apos;%1&apos; no es un archivo IGES: su primera línea no es un registro de la sección Start (IGES 5.3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is truncated: an IGES file ends with a Terminate section record, which is missing</source>
        <translation>&apos;%1&apos; está truncado: un archivo IGES termina con un registro de la sección Terminate, que falta</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not exist</source>
        <translation>&apos;%1&apos; no existe</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a file</source>
        <translation>&apos;%1&apos; no es un archivo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is empty</source>
        <translation>&apos;%1&apos; está vacío</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: %2</source>
        <translation>no se puede abrir &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>OpenCascade cannot parse &apos;%1&apos; as a STEP file (ISO 10303-21)</source>
        <translation>OpenCascade no puede analizar &apos;%1&apos; como archivo STEP (ISO 10303-21)</translation>
    </message>
    <message>
        <source>OpenCascade cannot parse &apos;%1&apos; as an IGES file</source>
        <translation>OpenCascade no puede analizar &apos;%1&apos; como archivo IGES</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no shape that OpenCascade can transfer (no solid, shell or face)</source>
        <translation>&apos;%1&apos; no contiene ninguna forma que OpenCascade pueda transferir (ningún cuerpo, lámina ni cara)</translation>
    </message>
    <message>
        <source>there is no %1 %2: the file has %3 (numbered from 0)</source>
        <translation>no existe el %1 %2: el archivo tiene %3 (numerados desde 0)</translation>
    </message>
    <message>
        <source>body</source>
        <translation>cuerpo</translation>
    </message>
    <message>
        <source>the file holds %1 bodies; body %2 (%3 mm³) is imported, choose another with the solid option</source>
        <translation>el archivo contiene %1 cuerpos; se importa el cuerpo %2 (%3 mm³); elija otro con la opción solid</translation>
    </message>
    <message>
        <source>the body in &apos;%1&apos; has no cylindrical, conical or toroidal face: it is not a turned part</source>
        <translation>el cuerpo de &apos;%1&apos; no tiene ninguna cara cilíndrica, cónica ni toroidal: no es una pieza torneada</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>eje</translation>
    </message>
    <message>
        <source>the body has revolved faces about %1 different axes; axis %2 (%3 mm² of revolved faces) is the part axis, choose another with the axis option</source>
        <translation>el cuerpo tiene caras de revolución alrededor de %1 ejes distintos; el eje %2 (%3 mm² de caras de revolución) es el eje de la pieza; elija otro con la opción axis</translation>
    </message>
    <message>
        <source>face %1 is %2, from z = %3 mm to z = %4 mm; it is not rotationally symmetric about the part axis and is left out of the profile</source>
        <translation>la cara %1 es %2, de z = %3 mm a z = %4 mm; no tiene simetría de revolución respecto al eje de la pieza y se excluye del perfil</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a STEP or IGES file: TolTurn reads files ending in .step, .stp, .iges or .igs</source>
        <translation>&apos;%1&apos; no es un archivo STEP ni IGES: TolTurn lee archivos con extensión .step, .stp, .iges o .igs</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no solid, shell or face</source>
        <translation>&apos;%1&apos; no contiene ningún cuerpo, lámina ni cara</translation>
    </message>
    <message>
        <source>reading &apos;%1&apos; failed: %2</source>
        <translation>error al leer &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: the number &apos;%3&apos; is beyond the largest real (about 1.8e308)</source>
        <translation>&apos;%1&apos;, línea %2: el número &apos;%3&apos; supera el mayor real (unos 1,8e308)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2</source>
        <translation>&apos;%1&apos; no es un modelo coherente: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; could not be read: OpenCascade stopped on an invalid model (%2); check the file in the CAD system that wrote it</source>
        <translation>No se pudo leer &apos;%1&apos;: OpenCascade se detuvo ante un modelo no válido (%2); revise el archivo en el sistema CAD que lo escribió</translation>
    </message>
    <message>
        <source>face %1 is written as a B-spline surface and was read as %2, which it is within 0.001 mm</source>
        <translation>la cara %1 está escrita como superficie B-spline y se leyó como %2, que es con una tolerancia de 0,001 mm</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2 refers to itself</source>
        <translation>«%1» no es un modelo coherente: %2 se refiere a sí mismo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a consistent model: %2 refers to %3, which leads back to %2 (a cycle of references)</source>
        <translation>«%1» no es un modelo coherente: %2 se refiere a %3, que lleva de vuelta a %2 (un ciclo de referencias)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; nests its entities %2 deep at %3, more than the %4 any CAD model needs</source>
        <translation>«%1» anida sus entidades %2 niveles en %3, más que los %4 que necesita cualquier modelo CAD</translation>
    </message>
    <message>
        <source>&apos;%1&apos; could not be read: OpenCascade failed on it (%2); check the file in the CAD system that wrote it</source>
        <translation>«%1» no se pudo leer: OpenCascade falló con él (%2); revise el archivo en el sistema CAD que lo escribió</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>cara %1</translation>
    </message>
    <message>
        <source>faces %1</source>
        <translation>caras %1</translation>
    </message>
    <message>
        <source>the flat of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a tool, conditions, cutting coefficients and a tolerance to evaluate it</source>
        <translation>la cara plana (%1), de z = %2 mm a z = %3 mm, se ha convertido en el elemento fresado %4; asígnele una herramienta, condiciones, coeficientes de corte y una tolerancia para evaluarlo</translation>
    </message>
    <message>
        <source>the keyway of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a tool, conditions, cutting coefficients and a tolerance to evaluate it</source>
        <translation>el chavetero (%1), de z = %2 mm a z = %3 mm, se ha convertido en el elemento fresado %4; asígnele una herramienta, condiciones, coeficientes de corte y una tolerancia para evaluarlo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; was not read: OpenCascade would not transfer shapes in millimetres (xstep.cascade.unit)</source>
        <translation>&apos;%1&apos; no se ha leído: OpenCascade no transfería las formas en milímetros (xstep.cascade.unit)</translation>
    </message>
</context>
<context>
    <name>StiffnessCommand</name>
    <message>
        <source>  %1: k1 = %2 N/mm, k2 = %3 N·mm/rad, k3 = %4 N·mm/rad; RMS residual %5 µm over %6 points</source>
        <translation>  %1: k1 = %2 N/mm, k2 = %3 N·mm/rad, k3 = %4 N·mm/rad; residuo RMS %5 µm en %6 puntos</translation>
    </message>
    <message>
        <source>Spindle–chuck springs from the test bar (Valiño et al. 2008 §III): Lc = %1 mm, Ø%2 mm, F_r = %3 N, F_t = %4 N, F_a = %5 N</source>
        <translation>Muelles husillo–plato a partir de la barra de prueba (Valiño et al. 2008 §III): Lc = %1 mm, Ø%2 mm, F_r = %3 N, F_t = %4 N, F_a = %5 N</translation>
    </message>
    <message>
        <source>radial</source>
        <translation>radial</translation>
    </message>
    <message>
        <source>tangential</source>
        <translation>tangencial</translation>
    </message>
    <message>
        <source>  tangential: not measured (no tangential_um column)</source>
        <translation>  tangencial: no medido (sin columna tangential_um)</translation>
    </message>
    <message>
        <source>The bar&apos;s own bending and the toolpost, subtracted before the fit: %1 % of the deviation measured farthest from the chuck.</source>
        <translation>Flexión propia de la barra y portaherramientas, restadas antes del ajuste: %1 % de la desviación medida más lejos del plato.</translation>
    </message>
    <message>
        <source>Test bar fit (Valiño et al. 2008 §III), tolturn-cli calibrate-stiffness, %1, %2: %3 points, RMS residual %4 µm</source>
        <translation>Ajuste de barra de prueba (Valiño et al. 2008 §III), tolturn-cli calibrate-stiffness, %1, %2: %3 puntos, residuo RMS %4 µm</translation>
    </message>
    <message>
        <source>Fit the spindle–chuck springs k1, k2, k3 (radial, and tangential where measured) to the measured deviation of a test bar turned in the chuck (Valiño et al. 2008 §III); --write stores them in the test bar&apos;s project, --into in another project on the same machine.</source>
        <translation>Ajustar los muelles husillo–plato k1, k2, k3 (radiales, y tangenciales donde se midieron) a la desviación medida de una barra de prueba torneada en el plato (Valiño et al. 2008 §III); --write los guarda en el proyecto de la barra, --into en otro proyecto de la misma máquina.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Imprimir el resultado como JSON.</translation>
    </message>
    <message>
        <source>Lc: distance of the front spindle bearing behind the chuck face, in mm (default: the project&apos;s characterisation).</source>
        <translation>Lc: distancia del rodamiento delantero del husillo detrás de la cara del plato, en mm (por defecto: la caracterización del proyecto).</translation>
    </message>
    <message>
        <source>Measured forces of the test cut in newtons, radial,tangential,axial (default: the project&apos;s force model).</source>
        <translation>Fuerzas medidas del corte de prueba en newtons, radial,tangencial,axial (por defecto: el modelo de fuerzas del proyecto).</translation>
    </message>
    <message>
        <source>Store the springs in the test bar&apos;s project and save it.</source>
        <translation>Guardar los muelles en el proyecto de la barra de prueba.</translation>
    </message>
    <message>
        <source>Store the springs in this project instead and save it.</source>
        <translation>Guardar los muelles en este otro proyecto.</translation>
    </message>
    <message>
        <source>Project of the test bar as cut: chuck only, its part, tool, material and pass.</source>
        <translation>Proyecto de la barra de prueba tal como se cortó: solo plato, su pieza, herramienta, material y pasada.</translation>
    </message>
    <message>
        <source>CSV of the measured bar: z_mm,radial_um[,tangential_um].</source>
        <translation>CSV de la barra medida: z_mm,radial_um[,tangential_um].</translation>
    </message>
    <message>
        <source>give a test bar project and a measurements file, and --write or --into, not both</source>
        <translation>indique un proyecto de barra de prueba y un archivo de mediciones, y --write o --into, no ambos</translation>
    </message>
    <message>
        <source>--pivot takes a length in mm, not &quot;%1&quot;</source>
        <translation>--pivot admite una longitud en mm, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>wrote %1: spindle–chuck springs</source>
        <translation>escrito %1: muelles husillo–plato</translation>
    </message>
    <message>
        <source>--load takes three numbers in newtons, radial,tangential,axial, each at most 1e6, not &quot;%1&quot;</source>
        <translation>--load toma tres números en newtons, radial,tangencial,axial, cada uno como mucho 1e6, no &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 is planned for machine &quot;%2&quot;, but the test bar was cut on &quot;%3&quot;: its springs are that machine&apos;s; nothing written</source>
        <translation>%1 está planificado para la máquina «%2», pero la barra de prueba se torneó en «%3»: sus muelles son de esa máquina; no se escribió nada</translation>
    </message>
    <message>
        <source>  tangential: not fitted (the warning above says why)</source>
        <translation>  tangencial: no ajustado (el aviso de arriba dice por qué)</translation>
    </message>
    <message>
        <source>Lc, the distance of the spindle bearing behind the chuck face, is not given: give it with --pivot MM, or in the project&apos;s characterisation</source>
        <translation>Lc, la distancia del rodamiento del husillo detrás de la cara del plato, no está indicada: indíquela con --pivot MM o en la caracterización del proyecto</translation>
    </message>
</context>
<context>
    <name>TableCopy</name>
    <message>
        <source>Copy Table as CSV</source>
        <translation>Copiar tabla como CSV</translation>
    </message>
</context>
<context>
    <name>TetMeshText</name>
    <message>
        <source>line %1 of the mesh is not a list of numbers: &quot;%2&quot;</source>
        <translation>la línea %1 de la malla no es una lista de números: «%2»</translation>
    </message>
    <message>
        <source>the mesh has no quadratic tetrahedra (C3D10)</source>
        <translation>la malla no contiene tetraedros cuadráticos (C3D10)</translation>
    </message>
    <message>
        <source>an element of the mesh uses node %1, which it does not define</source>
        <translation>un elemento de la malla usa el nodo %1, que la malla no define</translation>
    </message>
</context>
<context>
    <name>ToleranceVerdicts</name>
    <message>
        <source>feature %1 is not cut in this set-up (it lies in the chuck jaws or outside the supported length), so no deviation is predicted for it</source>
        <translation>el elemento %1 no se mecaniza en este montaje (está dentro de las garras del plato o fuera de la longitud apoyada), por lo que no se predice ninguna desviación para él</translation>
    </message>
    <message>
        <source>the limits of %1 at %2 mm cannot be formed</source>
        <translation>no se pueden formar los límites de %1 para %2 mm</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 13: D&apos;_Md &lt;= Dn + dDu and D&apos;_md &gt;= Dn + dDl</source>
        <translation>Fig. 4b, eq. 13: D&apos;_Md &lt;= Dn + dDu y D&apos;_md &gt;= Dn + dDl</translation>
    </message>
    <message>
        <source>Fig. 4b: eq. 13 fails as programmed, eq. 15 holds: 2|delta_TMd - delta_Tmd| &lt;= t</source>
        <translation>Fig. 4b: eq. 13 no se cumple tal como está programado, eq. 15 se cumple: 2|delta_TMd - delta_Tmd| &lt;= t</translation>
    </message>
    <message>
        <source>a constant tool offset of %1 µm on the diameter centres the size in its tolerance</source>
        <translation>una corrección constante de la herramienta de %1 µm en el diámetro centra la medida en su tolerancia</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| &gt; t</source>
        <translation>Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| &gt; t</translation>
    </message>
    <message>
        <source>there is no feature &apos;%1&apos; in the profile</source>
        <translation>no existe el elemento &apos;%1&apos; en el perfil</translation>
    </message>
    <message>
        <source>Perpendicularity of an axis to a face depends on how the part is aligned in the lathe; the axis recovers elastically after cutting, so the cutting-force deflection does not decide it (Valiño et al. 2008 §V.G.2).</source>
        <translation>La perpendicularidad de un eje respecto a una cara depende de cómo se alinea la pieza en el torno; el eje se recupera elásticamente tras el corte, por lo que la flexión debida a la fuerza de corte no la determina (Valiño et al. 2008 §V.G.2).</translation>
    </message>
    <message>
        <source>Coaxiality limits how far parts of the axis lie apart; the axis recovers elastically after cutting, so the error comes from set-up and alignment, not from the cutting-force deflection (Valiño et al. 2008 §V.H).</source>
        <translation>La coaxialidad limita la separación entre las distintas partes del eje; el eje se recupera elásticamente tras el corte, por lo que el error procede del montaje y la alineación, no de la flexión debida a la fuerza de corte (Valiño et al. 2008 §V.H).</translation>
    </message>
    <message>
        <source>The deflection under the cutting force is symmetrical about the axis of rotation and leaves no circular run-out; that comes from clamping deformation or misalignment (Valiño et al. 2008 §V.I).</source>
        <translation>La flexión bajo la fuerza de corte es simétrica respecto al eje de giro y no produce oscilación circular; esta procede de la deformación por sujeción o de la desalineación (Valiño et al. 2008 §V.I).</translation>
    </message>
    <message>
        <source>passes as programmed</source>
        <translation>cumple tal como está programado</translation>
    </message>
    <message>
        <source>passes after a constant offset</source>
        <translation>cumple tras una corrección constante</translation>
    </message>
    <message>
        <source>needs a profile correction</source>
        <translation>requiere una corrección del perfil</translation>
    </message>
    <message>
        <source>not predicted by this model</source>
        <translation>no lo predice este modelo</translation>
    </message>
    <message>
        <source>cannot be evaluated</source>
        <translation>no se puede evaluar</translation>
    </message>
    <message>
        <source>the predicted deviation of feature %1 is not finite, so nothing can be said of it</source>
        <translation>la desviación prevista del elemento %1 no es finita, así que no se puede decir nada de ella</translation>
    </message>
    <message>
        <source>Fig. 4b, eq. 15 holds for this tolerance, but the form does not fit the %1 µm zone that all of the feature&apos;s size tolerances allow</source>
        <translation>Fig. 4b, ec. 15 se cumple para esta tolerancia, pero la forma no cabe en la zona de %1 µm que permiten todas las tolerancias de tamaño del elemento</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with datums: a delta_n lies outside ±t/2 as programmed; a constant radial offset brings all within</source>
        <translation>ISO 1101 perfil de superficie, con referencias: un delta_n queda fuera de ±t/2 tal como está programado; una corrección radial constante los lleva todos dentro</translation>
    </message>
    <message>
        <source>a constant offset of %1 µm on the diameter (%2 µm normal to the surface) centres it in the zone</source>
        <translation>una corrección constante de %1 µm en el diámetro (%2 µm normal a la superficie) lo centra en la zona</translation>
    </message>
    <message>
        <source>a constant offset of %1 µm on the diameter brings every delta_n within ±t/2</source>
        <translation>una corrección constante de %1 µm en el diámetro lleva cada delta_n dentro de ±t/2</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with datums: no constant offset brings every delta_n within ±t/2</source>
        <translation>ISO 1101 perfil de superficie, con referencias: ninguna corrección constante lleva cada delta_n dentro de ±t/2</translation>
    </message>
    <message>
        <source>a constant tool offset of %1 µm on the diameter centres the size in the %2 µm zone that all of the feature&apos;s size tolerances allow</source>
        <translation>una corrección constante de la herramienta de %1 µm en el diámetro centra la medida en la zona de %2 µm que permiten todas las tolerancias de tamaño del elemento</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile, with a datum that locates it along the axis: every delta_n within ±t/2</source>
        <translation>ISO 1101 forma de superficie, con una referencia que la sitúa a lo largo del eje: cada delta_n dentro de ±t/2</translation>
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
        <translation>ISO 1101 forma de superficie, sin referencia (la zona flota a lo largo del eje)</translation>
    </message>
    <message>
        <source>ISO 1101 surface profile to a datum axis only (the zone may slide along it)</source>
        <translation>ISO 1101 forma de superficie, solo respecto a un eje de referencia (la zona puede deslizarse a lo largo de él)</translation>
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
        <translation>Fig. 4i, §V.J (eq. 16 y 24)</translation>
    </message>
    <message>
        <source>Fig. 4g, eq. 24 (face to the datum axis)</source>
        <translation>Fig. 4g, eq. 24 (cara respecto al eje de referencia)</translation>
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
        <translation>2 min sobre dz de max |delta_n - dz n_z|</translation>
    </message>
</context>
<context>
    <name>Toolpath</name>
    <message>
        <source>left centre</source>
        <translation>punto izquierdo</translation>
    </message>
    <message>
        <source>chuck face</source>
        <translation>plano del plato</translation>
    </message>
    <message>
        <source>%1 reaches within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): it is not turned there.</source>
        <translation>%1 llega a %2 mm del %3, donde la herramienta no entra (se mantiene a %4 mm): allí no se tornea.</translation>
    </message>
    <message>
        <source>%1 reach within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): they are not turned there.</source>
        <translation>%1 llegan a %2 mm del %3, donde la herramienta no entra (se mantiene a %4 mm): allí no se tornean.</translation>
    </message>
    <message>
        <source>Turn that end with the part turned end for end.</source>
        <translation>Tornee ese extremo con la pieza invertida.</translation>
    </message>
    <message>
        <source>Grip the part shorter, or turn that end in another set-up.</source>
        <translation>Sujete la pieza más corta o tornee ese extremo en otra sujeción.</translation>
    </message>
    <message>
        <source>%1 is narrower or tighter than the nose radius %2 mm: the nose cannot follow it and leaves it rounded.</source>
        <translation>%1 es más estrecho que el radio de punta de %2 mm: la punta no puede seguirlo y lo deja redondeado.</translation>
    </message>
    <message>
        <source>The planned roughing leaves up to %1 mm more than the finishing allowance of %2 mm: the finishing pass would cut it.</source>
        <translation>El desbaste planificado deja hasta %1 mm más que la creces de acabado de %2 mm: la pasada de acabado tendría que cortarlo.</translation>
    </message>
    <message>
        <source>The trailing edge angle of the tool is not known (holder entering angle and insert shape): falling contours are not checked.</source>
        <translation>No se conoce el ángulo del filo secundario de la herramienta (ángulo de posición del portaherramientas y forma de la plaquita): no se comprueban los contornos descendentes.</translation>
    </message>
    <message>
        <source>The right end face is held by a centre and is not faced: it is faced and centred before the part is set up.</source>
        <translation>La cara frontal derecha se apoya en un punto y no se refrenta: se refrenta y se hace el punto antes de sujetar la pieza.</translation>
    </message>
    <message>
        <source>The tool stops %1 mm short of the %2; the stock there is not turned.</source>
        <translation>La herramienta se detiene a %1 mm de %2; el material allí no se tornea.</translation>
    </message>
    <message>
        <source>left centre and driver</source>
        <translation>el punto izquierdo y el arrastrador</translation>
    </message>
    <message>
        <source>chuck jaws</source>
        <translation>las garras del plato</translation>
    </message>
    <message>
        <source>No roughing pass is planned: the finishing pass would cut up to %1 mm more than its depth of cut.</source>
        <translation>No hay pasada de desbaste planificada: la pasada de acabado cortaría hasta %1 mm más que su profundidad de corte.</translation>
    </message>
    <message>
        <source>%1 turns from the free end to z = %2 mm (from the held end); the rest of the outer contour is another operation&apos;s.</source>
        <translation>%1 tornea desde el extremo libre hasta z = %2 mm (desde el extremo sujetado); el resto del contorno exterior corresponde a otra operación.</translation>
    </message>
    <message>
        <source>%1 is tighter than the nose radius %2 mm: it is programmed as the sharp corner it rounds (a control&apos;s compensation cannot follow a concave arc tighter than the nose), and the nose leaves it rounded to %2 mm.</source>
        <translation>%1 es más cerrado que el radio de punta %2 mm: se programa como la esquina viva que redondea (la compensación de un control no puede seguir un arco cóncavo más cerrado que la punta), y la punta lo deja redondeado a %2 mm.</translation>
    </message>
    <message>
        <source>collet</source>
        <translation>pinza</translation>
    </message>
    <message>
        <source>%1: the recess of an undercut under its shoulder is not in this program (it turns the face down to the recess and the floor up to it): cut the recess with an undercut or grooving insert in a program of its own.</source>
        <translation>%1: el rebaje de una entalla bajo su resalte no está en este programa (tornea la cara hasta el rebaje y el fondo hasta él): corte el rebaje con una plaquita de entalla o de ranurar en un programa propio.</translation>
    </message>
    <message>
        <source>%1: goes back along z (an undercut) without a face and a floor beside it: the program follows it, but only an insert that fits under the overhang can cut it; the insert&apos;s outline is not checked.</source>
        <translation>%1: retrocede a lo largo de z (una entalla) sin una cara y un fondo a su lado: el programa lo sigue, pero solo una plaquita que quepa bajo el voladizo puede cortarlo; no se comprueba el contorno de la plaquita.</translation>
    </message>
    <message>
        <source>No roughing pass is planned: the finishing pass would bore up to %1 mm more than its depth of cut from the pilot hole.</source>
        <translation>No hay pasadas de desbaste planificadas: la pasada de acabado mandrinaría desde el agujero previo hasta %1 mm más que su profundidad de corte.</translation>
    </message>
    <message>
        <source>The bore needs more than %1 roughing levels at the planned depths of cut: the program stops there.</source>
        <translation>El agujero necesita más de %1 niveles de desbaste con las profundidades de corte planificadas: el programa se detiene ahí.</translation>
    </message>
    <message>
        <source>The boring levels leave up to %1 mm more than the finishing allowance of %2 mm: the finishing pass would cut it.</source>
        <translation>Los niveles de mandrinado dejan hasta %1 mm más que la creces de acabado de %2 mm: la pasada de acabado lo cortaría.</translation>
    </message>
    <message>
        <source>The trailing edge angle of the boring bar is not known (bar entering angle and insert shape): falling contours of the bore are not checked.</source>
        <translation>No se conoce el ángulo del filo secundario de la barra de mandrinar (ángulo de posición de la barra y forma de la plaquita): no se comprueban los contornos descendentes del agujero.</translation>
    </message>
    <message>
        <source>Boring bar %1 reaches z = %2 mm with its overhang of %3 mm: the bore from z = %4 mm to there is not bored. Set a longer overhang.</source>
        <translation>La barra de mandrinar %1 llega a z = %2 mm con su voladizo de %3 mm: el agujero desde z = %4 mm hasta ahí no se mandrina. Ajuste un voladizo mayor.</translation>
    </message>
    <message>
        <source>The pilot hole is not given (Set-up dock, Boring bar): the bore is taken as roughed to Ø%1 mm, its finishing allowance, before this program, and only its finishing pass is programmed.</source>
        <translation>No se indica el agujero previo (panel Preparación, Barra de mandrinar): se toma el agujero como desbastado a Ø%1 mm, su creces de acabado, antes de este programa, y solo se programa su pasada de acabado.</translation>
    </message>
    <message>
        <source>The pilot hole Ø%1 mm is wider than the bore less its finishing allowance (Ø%2 mm): the finishing pass cuts less than its depth of cut.</source>
        <translation>El agujero previo Ø%1 mm es mayor que el agujero menos su creces de acabado (Ø%2 mm): la pasada de acabado corta menos que su profundidad de corte.</translation>
    </message>
    <message>
        <source>Boring bar %1 (Ø%2 mm, edge %3 mm from its axis) does not fit in the Ø%4 mm hole it enters: it needs a hole of Ø%5 mm or more.</source>
        <translation>La barra de mandrinar %1 (Ø%2 mm, filo a %3 mm de su eje) no cabe en el agujero de Ø%4 mm en que entra: necesita un agujero de Ø%5 mm o más.</translation>
    </message>
    <message>
        <source>Boring bar %1 faces %2 only down to Ø%3 mm (further in, it would touch the opposite wall).</source>
        <translation>La barra de mandrinar %1 refrenta %2 solo hasta Ø%3 mm (más adentro tocaría la pared opuesta).</translation>
    </message>
    <message>
        <source>The bottom of the bore inside the pilot hole, Ø%1 mm, is the drill&apos;s: it is not bored.</source>
        <translation>El fondo del agujero dentro del agujero previo, Ø%1 mm, es el de la broca: no se mandrina.</translation>
    </message>
    <message>
        <source>The bar bores through to the held end: the chuck&apos;s or collet&apos;s bore must be free behind it.</source>
        <translation>La barra mandrina de lado a lado hasta el extremo sujeto: el paso del plato o de la pinza debe estar libre detrás.</translation>
    </message>
    <message>
        <source>The bore is bored from the free end with boring bar %1.</source>
        <translation>El agujero se mandrina desde el extremo libre con la barra de mandrinar %1.</translation>
    </message>
    <message>
        <source>The bottom of the bore, %1, is a cone or a radius down to the axis: the program finishes it to the axis, without the pilot hole&apos;s and the bar&apos;s limits of a flat bottom. Check that the bar clears the opposite wall there.</source>
        <translation>El fondo del agujero, %1, es un cono o un radio hasta el eje: el programa lo acaba hasta el eje, sin los límites del agujero previo y de la barra de un fondo plano. Compruebe que la barra no toca la pared opuesta ahí.</translation>
    </message>
    <message>
        <source>%1 is tighter than the nose radius %2 mm, and its neighbours give no corner to program instead: a control&apos;s compensation refuses it. Use an insert with a smaller nose, or --nose tip-path.</source>
        <translation>%1 es más cerrado que el radio de punta %2 mm, y sus vecinos no dan una esquina que programar en su lugar: la compensación de un control lo rechaza. Use una plaquita con radio de punta menor, o --nose tip-path.</translation>
    </message>
    <message>
        <source>The finishing pass cuts nothing: every outer feature of this set-up lies within the tool&apos;s stop of the %1. Grip the part shorter.</source>
        <translation>La pasada de acabado no corta nada: todos los elementos exteriores de este amarre quedan donde la herramienta se detiene antes de %1. Sujete la pieza más corta.</translation>
    </message>
    <message>
        <source>The pilot hole Ø%1 mm is as wide as the bore&apos;s narrowest Ø%2 mm or wider: nothing is left to bore there, and it stays the pilot hole&apos;s size, not the drawing&apos;s.</source>
        <translation>El agujero previo de Ø%1 mm es tan ancho como el tramo más estrecho del agujero, Ø%2 mm, o más: allí no queda nada que mandrinar, y se queda con la medida del agujero previo, no la del plano.</translation>
    </message>
    <message>
        <source>%1 falls at %2° in the feed direction, steeper than the insert&apos;s trailing edge (%3°) less the 2° of free cutting angle it needs: the finishing pass rides over it at %4° from z = %5 to %6 mm and leaves up to %7 mm of %8 uncut. Turn it from the other side or with a neutral tool.</source>
        <translation>%1 cae a %2° en la dirección del avance, más que el filo secundario de la plaquita (%3°) menos los 2° de ángulo libre que necesita: la pasada de acabado pasa por encima a %4° desde z = %5 hasta %6 mm y deja sin cortar hasta %7 mm de %8. Tornearlo desde el otro lado o con una herramienta neutra.</translation>
    </message>
    <message>
        <source>%1 falls at %2° in the feed direction, steeper than the insert&apos;s trailing edge (%3°) less the 2° of free cutting angle it needs: the finishing pass stops at z = %4 mm and leaves up to %5 mm of %6 uncut. Turn it from the other side or with a neutral tool.</source>
        <translation>%1 cae a %2° en la dirección del avance, más que el filo secundario de la plaquita (%3°) menos los 2° de ángulo libre que necesita: la pasada de acabado termina en z = %4 mm y deja sin cortar hasta %5 mm de %6. Tornearlo desde el otro lado o con una herramienta neutra.</translation>
    </message>
</context>
<context>
    <name>Undercuts</name>
    <message>
        <source>undercut %1 run-out</source>
        <translation>salida de la entalla %1</translation>
    </message>
    <message>
        <source>undercut %1 bottom</source>
        <translation>fondo de la entalla %1</translation>
    </message>
    <message>
        <source>undercut %1 radius</source>
        <translation>radio de la entalla %1</translation>
    </message>
    <message>
        <source>undercut %1 flank</source>
        <translation>flanco de la entalla %1</translation>
    </message>
    <message>
        <source>an undercut is cut into a corner between two features; the %1 contour has no such corner %2</source>
        <translation>una entalla se mecaniza en una esquina entre dos elementos; el contorno %1 no tiene ninguna esquina %2</translation>
    </message>
    <message>
        <source>a DIN 509 undercut sits where a cylinder meets a face, but corner %1 joins %2 and %3</source>
        <translation>una entalla DIN 509 se sitúa donde un cilindro se une con una cara, pero la esquina %1 une %2 y %3</translation>
    </message>
    <message>
        <source>corner %1 is an outside corner (face %2 falls away from cylinder %3): an undercut sits in the inside corner of a shoulder</source>
        <translation>la esquina %1 es una esquina exterior (la cara %2 desciende desde el cilindro %3): una entalla se sitúa en la esquina interior de un resalte</translation>
    </message>
    <message>
        <source>cylinder %1 has no diameter (Ø%2 mm) to size an undercut for</source>
        <translation>el cilindro %1 no tiene un diámetro (Ø%2 mm) para el que dimensionar una entalla</translation>
    </message>
    <message>
        <source>cylinder %1 is %2 mm long, not longer than the width f = %3 mm of undercut %4</source>
        <translation>el cilindro %1 mide %2 mm de largo, no más que el ancho f = %3 mm de la entalla %4</translation>
    </message>
    <message>
        <source>face %1 rises %2 mm above cylinder %3, but undercut %4 meets it %5 mm above: the shoulder is too low for it</source>
        <translation>la cara %1 se eleva %2 mm sobre el cilindro %3, pero la entalla %4 la alcanza %5 mm por encima: el resalte es demasiado bajo para ella</translation>
    </message>
    <message>
        <source>a groove is cut into a cylinder; %1 is not one</source>
        <translation>una ranura se mecaniza en un cilindro; %1 no lo es</translation>
    </message>
    <message>
        <source>the groove&apos;s width must be above zero, but is %1 mm</source>
        <translation>el ancho de la ranura debe ser mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the groove&apos;s depth must be above zero, but is %1 mm</source>
        <translation>la profundidad de la ranura debe ser mayor que cero, pero es %1 mm</translation>
    </message>
    <message>
        <source>the groove from z = %1 mm to z = %2 mm must lie inside %3 (z %4 … %5 mm)</source>
        <translation>la ranura de z = %1 mm a z = %2 mm debe quedar dentro de %3 (z %4 … %5 mm)</translation>
    </message>
    <message>
        <source>a groove %1 mm deep would reach the axis from Ø%2 mm</source>
        <translation>una ranura de %1 mm de profundidad llegaría al eje desde Ø%2 mm</translation>
    </message>
    <message>
        <source>groove flank</source>
        <translation>flanco de la ranura</translation>
    </message>
    <message>
        <source>groove bottom Ø%1</source>
        <translation>fondo de la ranura Ø%1</translation>
    </message>
</context>
<context>
    <name>VerifyFeCommand</name>
    <message>
        <source>Solid check of %1 (%2): E = %3 MPa, nu = %4</source>
        <translation>Comprobación con sólido de %1 (%2): E = %3 MPa, nu = %4</translation>
    </message>
    <message>
        <source>Force at each station: Fr = %1 N, Ft = %2 N, Fa = %3 N</source>
        <translation>Fuerza en cada estación: Fr = %1 N, Ft = %2 N, Fa = %3 N</translation>
    </message>
    <message>
        <source>Mesh: C3D10 of at most %1 mm, %2 nodes, %3 elements, %4 degrees of freedom; gmsh %5 s, CalculiX %6 s, beam %7 ms</source>
        <translation>Malla: C3D10 de como mucho %1 mm, %2 nodos, %3 elementos, %4 grados de libertad; gmsh %5 s, CalculiX %6 s, viga %7 ms</translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>nota: %1</translation>
    </message>
    <message>
        <source>Check the beam against a solid model: the part meshed in quadratic tetrahedra with gmsh, held as its clamping holds it, loaded at N tool positions and solved with CalculiX; beam and solid deflection per station with the difference, the mesh size and degrees of freedom.</source>
        <translation>Comprobar la viga con un modelo sólido: la pieza mallada en tetraedros cuadráticos con gmsh, sujeta tal como la sostiene su sujeción, cargada en N posiciones de la herramienta y resuelta con CalculiX; deflexión de la viga y del sólido por estación con la diferencia, el tamaño de malla y los grados de libertad.</translation>
    </message>
    <message>
        <source>Print the result as JSON.</source>
        <translation>Imprimir el resultado como JSON.</translation>
    </message>
    <message>
        <source>Tool positions along the part, 1 to %1 (default 5).</source>
        <translation>Posiciones de la herramienta a lo largo de la pieza, de 1 a %1 (por defecto 5).</translation>
    </message>
    <message>
        <source>Largest element edge in mm (default: a fifth of the smallest turned diameter, at least 1 mm).</source>
        <translation>Arista de elemento más larga en mm (por defecto: una quinta parte del menor diámetro torneado, como mínimo 1 mm).</translation>
    </message>
    <message>
        <source>Forces radial, tangential, axial in N instead of the pass&apos;s.</source>
        <translation>Fuerzas radial, tangencial y axial en N en lugar de las de la pasada.</translation>
    </message>
    <message>
        <source>Report the progress on standard error, as lines &quot;progress F&quot; with F from 0 to 1.</source>
        <translation>Informar del progreso en la salida de error estándar, como líneas «progress F» con F de 0 a 1.</translation>
    </message>
    <message>
        <source>The project file.</source>
        <translation>Archivo de proyecto.</translation>
    </message>
    <message>
        <source>--stations: &quot;%1&quot; is not a whole number from 1 to %2</source>
        <translation>--stations: «%1» no es un número entero de 1 a %2</translation>
    </message>
    <message>
        <source>--mesh-size: &quot;%1&quot; is not a length from 0.2 to 100 mm</source>
        <translation>--mesh-size: «%1» no es una longitud de 0,2 a 100 mm</translation>
    </message>
    <message>
        <source>--load: &quot;%1&quot; is not three forces Fr,Ft,Fa in N</source>
        <translation>--load: «%1» no son tres fuerzas Fr,Ft,Fa en N</translation>
    </message>
    <message>
        <source>Largest radial difference: %1 % of the largest deflection</source>
        <translation>Mayor diferencia radial: %1 % de la mayor deflexión</translation>
    </message>
    <message>
        <source>Beam: corrected for the root in the jaws and the shoulders (docs/solid-fe.md); Timoshenko: without the corrections</source>
        <translation>Viga: corregida por el empotramiento en las garras y los resaltes (docs/solid-fe.md); Timoshenko: sin las correcciones</translation>
    </message>
    <message>
        <source>Beam: Timoshenko, without the corrections (--uncorrected-beam)</source>
        <translation>Viga: Timoshenko, sin las correcciones (--uncorrected-beam)</translation>
    </message>
    <message>
        <source>  z [mm]   D [mm]   radial deflection [um]: beam    solid   beam-solid [%]   tangential [um]: beam    solid   Timoshenko radial [um]</source>
        <translation>  z [mm]   D [mm]     deflexión radial [um]: viga   sólido  viga-sólido [%]    tangencial [um]: viga   sólido   Timoshenko radial [um]</translation>
    </message>
    <message>
        <source>Compare the beam without its corrections for the root in the jaws and the shoulders.</source>
        <translation>Comparar la viga sin sus correcciones del empotramiento en las garras y de los resaltes.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Tolerance-aware planning of CNC turning.</source>
        <translation>Planificación del torneado CNC teniendo en cuenta las tolerancias.</translation>
    </message>
    <message>
        <source>Project file to open (.tolturn).</source>
        <translation>Archivo de proyecto que se va a abrir (.tolturn).</translation>
    </message>
</context>
<context>
    <name>tolturn::AboutDialog</name>
    <message>
        <source>&lt;p&gt;Tolerance-aware planning of CNC turning: deflection of machine, workpiece and tool, ISO 286 and ISO 1101 verdicts, and cutting conditions that hold them.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later). There is no warranty.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Planificación del torneado CNC teniendo en cuenta las tolerancias: flexión de la máquina, la pieza y la herramienta, veredictos ISO 286 e ISO 1101, y condiciones de corte que permiten cumplirlos.&lt;/p&gt;&lt;p&gt;Publicado bajo la Licencia Pública General de GNU, versión 3 o posterior (GPL-3.0-or-later). No se ofrece ninguna garantía.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Built with</source>
        <translation>Compilado con</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Biblioteca</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>Versión</translation>
    </message>
    <message>
        <source>Licence</source>
        <translation>Licencia</translation>
    </message>
    <message>
        <source>About TolTurn</source>
        <translation>Acerca de TolTurn</translation>
    </message>
</context>
<context>
    <name>tolturn::AdaptiveTab</name>
    <message>
        <source>The pass of the plan simulated under constant-force control</source>
        <translation>La pasada del plan simulada con control de fuerza constante</translation>
    </message>
    <message>
        <source>Force [N]</source>
        <translation>Fuerza [N]</translation>
    </message>
    <message>
        <source>Feed [mm/rev]</source>
        <translation>Avance [mm/rev]</translation>
    </message>
    <message>
        <source>Deviation [µm]</source>
        <translation>Desviación [µm]</translation>
    </message>
    <message>
        <source>Roughness Ra [µm]</source>
        <translation>Rugosidad Ra [µm]</translation>
    </message>
    <message>
        <source>Depth of cut [mm]</source>
        <translation>Profundidad de corte [mm]</translation>
    </message>
    <message>
        <source>Machine noise (Čuš &amp; Župerl §2.4): the standard deviation of the measured force. The paper states no level; none unless given.</source>
        <translation>Ruido de máquina (Čuš &amp; Župerl §2.4): la desviación típica de la fuerza medida. El artículo no da un nivel; ninguno si no se indica.</translation>
    </message>
    <message>
        <source>Machine noise:</source>
        <translation>Ruido de máquina:</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Scheduled f [mm/rev]</source>
        <translation>f programada por elemento [mm/rev]</translation>
    </message>
    <message>
        <source>Programmed f [mm/rev]</source>
        <translation>f programada [mm/rev]</translation>
    </message>
    <message>
        <source>Limited by</source>
        <translation>Limitado por</translation>
    </message>
    <message>
        <source>The finishing pass feature by feature: the largest feed of the plan&apos;s feed range that holds the feature&apos;s tolerances and the pass&apos;s roughness, power and force limits</source>
        <translation>La pasada de acabado elemento por elemento: el mayor avance del rango de la planificación que mantiene las tolerancias del elemento y los límites de rugosidad, potencia y fuerza de la pasada</translation>
    </message>
    <message>
        <source>&lt;b&gt;Feed schedule of the finishing pass&lt;/b&gt;</source>
        <translation>&lt;b&gt;Programa de avances de la pasada de acabado&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Pass %1 (roughing)</source>
        <translation>Pasada %1 (desbaste)</translation>
    </message>
    <message>
        <source>Pass %1 (finishing)</source>
        <translation>Pasada %1 (acabado)</translation>
    </message>
    <message>
        <source>No pass to simulate.</source>
        <translation>No hay pasada que simular.</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>depth of cut</source>
        <translation>profundidad de corte</translation>
    </message>
    <message>
        <source>programmed feed</source>
        <translation>avance programado</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptativo</translation>
    </message>
    <message>
        <source>Set force %1 N (the programmed feed&apos;s at a_p %2 mm). In the cut %3 s at the programmed feed, %4 s adaptive (%5 % saved); peak force %6 N and %7 N; deviation %8–%9 µm and %10–%11 µm.</source>
        <translation>Fuerza de consigna %1 N (la del avance programado con a_p %2 mm). En corte %3 s con el avance programado, %4 s adaptativo (%5 % ahorrado); fuerza máxima %6 N y %7 N; desviación %8–%9 µm y %10–%11 µm.</translation>
    </message>
    <message>
        <source>No feed schedule: %1</source>
        <translation>Sin programa de avances: %1</translation>
    </message>
    <message>
        <source>kept: %1 is not held at any feed of the range</source>
        <translation>conservado: %1 no se cumple con ningún avance del rango</translation>
    </message>
    <message>
        <source>Finishing pass: %1 s at the programmed feed, %2 s scheduled (%3 %). Tick Feed schedule on the G-code tab to program it.</source>
        <translation>Pasada de acabado: %1 s con el avance programado, %2 s según el programa (%3 %). Marque Programa de avances en la pestaña Código G para programarlo.</translation>
    </message>
</context>
<context>
    <name>tolturn::CadFileController</name>
    <message>
        <source>Reading %1…</source>
        <translation>Leyendo %1…</translation>
    </message>
    <message>
        <source>Import of %1 cancelled; the project is unchanged.</source>
        <translation>Importación de %1 cancelada; el proyecto no ha cambiado.</translation>
    </message>
    <message>
        <source>Import of %1 cancelled.</source>
        <translation>Importación de %1 cancelada.</translation>
    </message>
    <message>
        <source>Cannot import %1</source>
        <translation>No se puede importar %1</translation>
    </message>
    <message>
        <source>The part was not imported; the current project is unchanged.

%1</source>
        <translation>No se ha importado la pieza; el proyecto actual no ha cambiado.

%1</translation>
    </message>
    <message>
        <source>%1 could not be imported:</source>
        <translation>No se ha podido importar %1:</translation>
    </message>
    <message>
        <source>Imported %1: %2 outer and %3 inner features, %4 warning(s); set material, machine, tool and clamping, then save.</source>
        <translation>Se ha importado %1: %2 elementos exteriores y %3 interiores, %4 aviso(s); defina el material, la máquina, la herramienta y la sujeción, y después guarde.</translation>
    </message>
    <message>
        <source>Imported from %1; left out or noted:</source>
        <translation>Importado de %1; elementos excluidos u observaciones:</translation>
    </message>
    <message>
        <source>Cannot export %1</source>
        <translation>No se puede exportar %1</translation>
    </message>
    <message>
        <source>Exported the part as a revolved solid to %1</source>
        <translation>Se ha exportado la pieza como cuerpo de revolución a %1</translation>
    </message>
    <message>
        <source>Extracting the part from %1…</source>
        <translation>Extrayendo la pieza de %1…</translation>
    </message>
</context>
<context>
    <name>tolturn::CadReaderProcess</name>
    <message>
        <source>The CAD reader &apos;%1&apos; is missing: TolTurn reads STEP and IGES files with tolturn-cli, which is installed beside it. Install TolTurn again.</source>
        <translation>Falta el lector CAD «%1»: TolTurn lee archivos STEP e IGES con tolturn-cli, instalado junto a él. Vuelva a instalar TolTurn.</translation>
    </message>
    <message>
        <source>No temporary folder for the import: %1</source>
        <translation>No hay carpeta temporal para la importación: %1</translation>
    </message>
    <message>
        <source>The CAD reader &apos;%1&apos; could not be started: %2</source>
        <translation>No se pudo iniciar el lector CAD «%1»: %2</translation>
    </message>
    <message>
        <source>Reading %1 ended the CAD reader (OpenCascade) abnormally; the program and the project are not affected. The file is probably damaged: check it in the CAD system that wrote it.%2</source>
        <translation>La lectura de %1 terminó el lector CAD (OpenCascade) de forma anómala; el programa y el proyecto no se ven afectados. El archivo probablemente está dañado: revíselo en el sistema CAD que lo escribió.%2</translation>
    </message>
    <message>
        <source>The CAD reader gave no result for %1 (exit code %2): %3 %4</source>
        <translation>El lector CAD no dio resultado para %1 (código de salida %2): %3 %4</translation>
    </message>
</context>
<context>
    <name>tolturn::DeflectionPanel</name>
    <message>
        <source>Outer contour</source>
        <translation>Contorno exterior</translation>
    </message>
    <message>
        <source>Inner contour (bores)</source>
        <translation>Contorno interior (agujeros)</translation>
    </message>
    <message>
        <source>Radial deviation by contribution</source>
        <translation>Desviación radial por contribución</translation>
    </message>
    <message>
        <source>Tangential deviation by contribution</source>
        <translation>Desviación tangencial por contribución</translation>
    </message>
    <message>
        <source>Diameter error</source>
        <translation>Error de diámetro</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>spindle–chuck / supports</source>
        <translation>husillo–plato / apoyos</translation>
    </message>
    <message>
        <source>workpiece</source>
        <translation>pieza</translation>
    </message>
    <message>
        <source>toolpost</source>
        <translation>torreta</translation>
    </message>
    <message>
        <source>thermal</source>
        <translation>térmica</translation>
    </message>
    <message>
        <source>Radial deviation (material left on the surface)</source>
        <translation>Desviación radial (material sobrante en la superficie)</translation>
    </message>
    <message>
        <source>Tangential deviation</source>
        <translation>Desviación tangencial</translation>
    </message>
    <message>
        <source>diameter error</source>
        <translation>error de diámetro</translation>
    </message>
    <message>
        <source>Diameter error: machined minus nominal</source>
        <translation>Error de diámetro: mecanizado menos nominal</translation>
    </message>
    <message>
        <source>Forces (%1): Fc %2 N, Ff %3 N, Fp %4 N · pass %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm</source>
        <translation>Fuerzas (%1): Fc %2 N, Ff %3 N, Fp %4 N · pasada %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm</translation>
    </message>
    <message>
        <source>Error: </source>
        <translation>Error: </translation>
    </message>
    <message>
        <source>Warning: </source>
        <translation>Aviso: </translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [%1]</source>
        <translation>z desde el extremo izquierdo de la pieza [%1]</translation>
    </message>
    <message>
        <source>deviation [%1]</source>
        <translation>desviación [%1]</translation>
    </message>
    <message>
        <source>diameter error [%1]</source>
        <translation>error de diámetro [%1]</translation>
    </message>
    <message>
        <source>Face conicity</source>
        <translation>Conicidad de las caras</translation>
    </message>
    <message>
        <source>Radial deviation: material left on the surface, δ_T = δ_sc + δ_tp + δ_p + δ_th (Valiño et al. 2008, eq. 2). Diameter error: 2 (r - r_nominal) with the radial and tangential deviation combined exactly. Face conicity: the axial run-out e = h · tan θ of each faced surface, tan θ = dδ/dz at the face (eq. 12).</source>
        <translation>Desviación radial: material sobrante en la superficie, δ_T = δ_sc + δ_tp + δ_p + δ_th (Valiño et al. 2008, ec. 2). Error de diámetro: 2 (r - r_nominal), combinando exactamente la desviación radial y la tangencial. Conicidad de las caras: la oscilación axial e = h · tan θ de cada superficie refrentada, tan θ = dδ/dz en la cara (ec. 12).</translation>
    </message>
    <message>
        <source>axial run-out e of each face</source>
        <translation>oscilación axial e de cada cara</translation>
    </message>
    <message>
        <source>Face conicity: axial run-out of each face</source>
        <translation>Conicidad de las caras: oscilación axial de cada cara</translation>
    </message>
    <message>
        <source>axial run-out e [%1]</source>
        <translation>oscilación axial e [%1]</translation>
    </message>
    <message>
        <source>%1, compliant end of the machine range</source>
        <translation>%1, extremo flexible del rango de máquinas</translation>
    </message>
    <message>
        <source>%1 over the machine&apos;s stiffness range</source>
        <translation>%1 en el rango de rigidez de la máquina</translation>
    </message>
    <message>
        <source>The predicted deviation of every feature appears here once a part is open.</source>
        <translation>La desviación prevista de cada elemento aparece aquí en cuanto se abre una pieza.</translation>
    </message>
    <message>
        <source>total, physics + learned</source>
        <translation>total, modelo físico + aprendido</translation>
    </message>
    <message>
        <source>diameter error, physics + learned</source>
        <translation>error de diámetro, modelo físico + aprendido</translation>
    </message>
    <message>
        <source>Physics + learned (%1): what was learned of the machine from its measured parts is added to the physics; the band is ± the RMS error on parts not learned from (%2 µm).</source>
        <translation>Modelo físico + aprendido (%1): lo aprendido de la máquina a partir de sus piezas medidas se suma al modelo físico; la banda es ± el error RMS en las piezas no aprendidas (%2 µm).</translation>
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
        <translation>barra de mandrinar</translation>
    </message>
    <message>
        <source> · bores: bar %1, L/D %2, Fc %3 N, Ff %4 N, Fp %5 N, %6 µm/N at its tip</source>
        <translation> · agujeros: barra %1, L/D %2, Fc %3 N, Ff %4 N, Fp %5 N, %6 µm/N en la punta</translation>
    </message>
    <message>
        <source>z from the held (right) end [%1]</source>
        <translation>z desde el extremo sujetado (derecho) [%1]</translation>
    </message>
</context>
<context>
    <name>tolturn::DiagnosticsPanel</name>
    <message>
        <source>Severity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ubicación</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>aviso</translation>
    </message>
</context>
<context>
    <name>tolturn::EndMillingExampleDialog</name>
    <message>
        <source>Čuš &amp; Župerl end-milling example</source>
        <translation>Ejemplo de fresado frontal de Čuš y Župerl</translation>
    </message>
    <message>
        <source>Force [N]</source>
        <translation>Fuerza [N]</translation>
    </message>
    <message>
        <source>Feed rate [mm/min]</source>
        <translation>Velocidad de avance [mm/min]</translation>
    </message>
    <message>
        <source>Spindle speed [1/min]</source>
        <translation>Velocidad del husillo [1/min]</translation>
    </message>
    <message>
        <source>Roughness Ra, M5 [µm]</source>
        <translation>Rugosidad Ra, M5 [µm]</translation>
    </message>
    <message>
        <source>Machine noise: standard deviation of the measured force (004 gives no level)</source>
        <translation>Ruido de máquina: desviación típica de la fuerza medida (004 no da un nivel)</translation>
    </message>
    <message>
        <source>Share of a change of chip load the spindle speed takes (0: the feed alone)</source>
        <translation>Fracción de un cambio del espesor de viruta que asume la velocidad del husillo (0: solo el avance)</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>Ruido</translation>
    </message>
    <message>
        <source>Speed share</source>
        <translation>Fracción de velocidad</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Artículo</translation>
    </message>
    <message>
        <source>Speed [1/min]</source>
        <translation>Velocidad [1/min]</translation>
    </message>
    <message>
        <source>Ra, M5 [µm]</source>
        <translation>Ra, M5 [µm]</translation>
    </message>
    <message>
        <source>paper: 181.1 N held</source>
        <translation>artículo: 181,1 N mantenidos</translation>
    </message>
    <message>
        <source>paper: 324.61 mm/min after control</source>
        <translation>artículo: 324,61 mm/min tras el control</translation>
    </message>
    <message>
        <source>paper: 2201 1/min after control</source>
        <translation>artículo: 2201 1/min tras el control</translation>
    </message>
    <message>
        <source>paper: Ra 0.79 µm produced</source>
        <translation>artículo: Ra 0,79 µm obtenida</translation>
    </message>
    <message>
        <source>Table 1, simulation 5: from 430.41 mm/min and 1610 1/min to 181.1 N</source>
        <translation>Tabla 1, simulación 5: de 430,41 mm/min y 1610 1/min a 181,1 N</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>without control</source>
        <translation>sin control</translation>
    </message>
    <message>
        <source>adaptive</source>
        <translation>adaptativo</translation>
    </message>
    <message>
        <source>Force network 8–15–3 (ArcTangent, back-propagation) trained on the mean forces of the linear edge-force model for Al7075-T6 (004&apos;s cut data are not published): %1 % RMS error on cut data it has not seen. Tool Ø%2 mm, %3 flutes, down milling %4 mm wide, %5 mm deep (the depth at which the model gives the paper&apos;s 181.1 N at its controlled conditions). PSO-NN off line: %6 mm/min at %7 1/min within %8 N. Ra from the printed M5 (eq. 6), which does not reproduce the paper&apos;s table; the spindle follows the feed drive&apos;s eq. 1 (004 gives no spindle model). * outside the network&apos;s training range.</source>
        <translation>Red de fuerzas 8–15–3 (arcotangente, retropropagación) entrenada con las fuerzas medias del modelo lineal de fuerzas de filo para Al7075-T6 (los datos de corte de 004 no están publicados): %1 % de error eficaz en datos de corte que no ha visto. Herramienta Ø%2 mm, %3 filos, fresado en concordancia de %4 mm de ancho y %5 mm de profundidad (la profundidad a la que el modelo da los 181,1 N del artículo en sus condiciones controladas). PSO-NN fuera de línea: %6 mm/min a %7 1/min dentro de %8 N. Ra del M5 impreso (ec. 6), que no reproduce la tabla del artículo; el husillo sigue la ec. 1 del accionamiento de avance (004 no da modelo del husillo). * fuera del rango de entrenamiento de la red.</translation>
    </message>
</context>
<context>
    <name>tolturn::FeaturePanel</name>
    <message>
        <source>z of the start, from the part&apos;s left end</source>
        <translation>z del inicio, desde el extremo izquierdo de la pieza</translation>
    </message>
    <message>
        <source>Diameter at the start</source>
        <translation>Diámetro en el inicio</translation>
    </message>
    <message>
        <source>z of the end</source>
        <translation>z del final</translation>
    </message>
    <message>
        <source>Diameter at the end</source>
        <translation>Diámetro en el final</translation>
    </message>
    <message>
        <source>Where the step is, inside the cylinder</source>
        <translation>Posición del escalón dentro del cilindro</translation>
    </message>
    <message>
        <source>Diameter after the step</source>
        <translation>Diámetro después del escalón</translation>
    </message>
    <message>
        <source>Insert &amp;Step</source>
        <translation>&amp;Insertar escalón</translation>
    </message>
    <message>
        <source>Chamfer leg (45°) or radius</source>
        <translation>Cateto del chaflán (45°) o radio</translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation>&amp;Eliminar elemento</translation>
    </message>
    <message>
        <source>Make C&amp;one</source>
        <translation>Convertir en c&amp;ono</translation>
    </message>
    <message>
        <source>Depth of the bore from this end face; the part&apos;s length bores through</source>
        <translation>Profundidad del agujero desde esta cara extrema; la longitud de la pieza lo hace pasante</translation>
    </message>
    <message>
        <source>Diameter of the bore</source>
        <translation>Diámetro del agujero</translation>
    </message>
    <message>
        <source>&amp;Bore from This Face</source>
        <translation>&amp;Agujero desde esta cara</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Esquinas</translation>
    </message>
    <message>
        <source>Start z:</source>
        <translation>z inicial:</translation>
    </message>
    <message>
        <source>Start Ø:</source>
        <translation>Ø inicial:</translation>
    </message>
    <message>
        <source>End z:</source>
        <translation>z final:</translation>
    </message>
    <message>
        <source>End Ø:</source>
        <translation>Ø final:</translation>
    </message>
    <message>
        <source>Step (cylinders)</source>
        <translation>Escalón (cilindros)</translation>
    </message>
    <message>
        <source>At z:</source>
        <translation>En z:</translation>
    </message>
    <message>
        <source>To Ø:</source>
        <translation>A Ø:</translation>
    </message>
    <message>
        <source>Break a corner</source>
        <translation>Romper una arista</translation>
    </message>
    <message>
        <source>Size:</source>
        <translation>Tamaño:</translation>
    </message>
    <message>
        <source>Chamfer start</source>
        <translation>Chaflán al inicio</translation>
    </message>
    <message>
        <source>Chamfer end</source>
        <translation>Chaflán al final</translation>
    </message>
    <message>
        <source>Round start</source>
        <translation>Redondeo al inicio</translation>
    </message>
    <message>
        <source>Round end</source>
        <translation>Redondeo al final</translation>
    </message>
    <message>
        <source>Bore (solid part, end face)</source>
        <translation>Agujero (pieza maciza, cara extrema)</translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation>Profundidad:</translation>
    </message>
    <message>
        <source>Ø:</source>
        <translation>Ø:</translation>
    </message>
    <message>
        <source>Click a feature of the drawing to edit it.</source>
        <translation>Haga clic en un elemento del dibujo para editarlo.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; %2 — %3, %4 contour</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; %2 — %3, contorno %4</translation>
    </message>
    <message>
        <source>Make C&amp;ylinder</source>
        <translation>Convertir en ci&amp;lindro</translation>
    </message>
    <message>
        <source>Move corner of %1</source>
        <translation>Mover esquina de %1</translation>
    </message>
    <message>
        <source>Move corner to z %1, Ø %2</source>
        <translation>Mover esquina a z %1, Ø %2</translation>
    </message>
    <message>
        <source>Insert step into %1</source>
        <translation>Insertar escalón en %1</translation>
    </message>
    <message>
        <source>Round corner of %1</source>
        <translation>Redondear esquina de %1</translation>
    </message>
    <message>
        <source>Chamfer corner of %1</source>
        <translation>Achaflanar esquina de %1</translation>
    </message>
    <message>
        <source>Make %1 a cylinder</source>
        <translation>Convertir %1 en cilindro</translation>
    </message>
    <message>
        <source>Make %1 a cone</source>
        <translation>Convertir %1 en cono</translation>
    </message>
    <message>
        <source>Bore from %1</source>
        <translation>Agujero desde %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Eliminar %1</translation>
    </message>
    <message>
        <source>Make R&amp;ound</source>
        <translation>Convertir en &amp;redondeo</translation>
    </message>
    <message>
        <source>Make C&amp;hamfer</source>
        <translation>Convertir en c&amp;haflán</translation>
    </message>
    <message>
        <source>Make %1 an edge round</source>
        <translation>Convertir %1 en redondeo de arista</translation>
    </message>
    <message>
        <source>Make %1 a chamfer</source>
        <translation>Convertir %1 en chaflán</translation>
    </message>
    <message>
        <source>Where the groove starts, inside the cylinder (its left flank)</source>
        <translation>Dónde empieza la ranura, dentro del cilindro (su flanco izquierdo)</translation>
    </message>
    <message>
        <source>Width of the groove along z</source>
        <translation>Ancho de la ranura a lo largo de z</translation>
    </message>
    <message>
        <source>Depth of the groove, radially</source>
        <translation>Profundidad de la ranura, en dirección radial</translation>
    </message>
    <message>
        <source>Insert &amp;Groove</source>
        <translation>Insertar &amp;ranura</translation>
    </message>
    <message>
        <source>Undercut start</source>
        <translation>Inicio de la entalla</translation>
    </message>
    <message>
        <source>Undercut end</source>
        <translation>Fin de la entalla</translation>
    </message>
    <message>
        <source>Groove and undercut (cylinders)</source>
        <translation>Ranura y entalla (cilindros)</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>Ancho:</translation>
    </message>
    <message>
        <source>DIN 509 form E (cylinder)</source>
        <translation>DIN 509 forma E (cilindro)</translation>
    </message>
    <message>
        <source>DIN 509 form F (cylinder and face)</source>
        <translation>DIN 509 forma F (cilindro y cara)</translation>
    </message>
    <message>
        <source>The undercut is sized for the cylinder&apos;s diameter by DIN 509 Table 1 and cut into the corner where the cylinder meets a shoulder</source>
        <translation>La entalla se dimensiona según el diámetro del cilindro conforme a DIN 509 tabla 1 y se mecaniza en la esquina donde el cilindro se une con un resalte</translation>
    </message>
    <message>
        <source>DIN 509 Table 1 for Ø%1 mm: E or F %2 × %3 (r × t1), width f %4 mm, recess into the face t2 %5 mm (form F)</source>
        <translation>DIN 509 tabla 1 para Ø%1 mm: E o F %2 × %3 (r × t1), ancho f %4 mm, rebaje en la cara t2 %5 mm (forma F)</translation>
    </message>
    <message>
        <source>Insert groove into %1</source>
        <translation>Insertar ranura en %1</translation>
    </message>
    <message>
        <source>Insert DIN 509 undercut at %1</source>
        <translation>Insertar entalla DIN 509 en %1</translation>
    </message>
</context>
<context>
    <name>tolturn::FileController</name>
    <message>
        <source>TolTurn projects (*.tolturn *.json);;All files (*)</source>
        <translation>Proyectos de TolTurn (*.tolturn *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>New part</source>
        <translation>Pieza nueva</translation>
    </message>
    <message>
        <source>New project: a plain bar to shape</source>
        <translation>Proyecto nuevo: una barra lisa a la que dar forma</translation>
    </message>
    <message>
        <source>Cannot open %1</source>
        <translation>No se puede abrir %1</translation>
    </message>
    <message>
        <source>The file was not opened; the current project is unchanged.

%1</source>
        <translation>No se ha abierto el archivo; el proyecto actual no ha cambiado.

%1</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Se ha abierto %1</translation>
    </message>
    <message>
        <source>the unsaved project &quot;%1&quot;</source>
        <translation>el proyecto sin guardar &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Cannot recover %1</source>
        <translation>No se puede recuperar %1</translation>
    </message>
    <message>
        <source>The copy %1 cannot be read; it is kept.

%2</source>
        <translation>No se puede leer la copia %1; se conserva.

%2</translation>
    </message>
    <message>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation>Se ha recuperado %1 tal como estaba el %2; guárdelo para conservarlo.</translation>
    </message>
    <message>
        <source>Cannot export the report</source>
        <translation>No se puede exportar el informe</translation>
    </message>
    <message numerus="yes">
        <source>Report written to %1 (%n page(s))</source>
        <translation>
            <numerusform>Informe escrito en %1 (%n página)</numerusform>
            <numerusform>Informe escrito en %1 (%n páginas)</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot save %1</source>
        <translation>No se puede guardar %1</translation>
    </message>
    <message>
        <source>The project was not saved; the file on disk is unchanged.

%1</source>
        <translation>No se ha guardado el proyecto; el archivo en disco no ha cambiado.

%1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Se ha guardado %1</translation>
    </message>
    <message>
        <source>Writing the report…</source>
        <translation>Escribiendo el informe…</translation>
    </message>
    <message>
        <source>Report cancelled; nothing was written.</source>
        <translation>Informe cancelado; no se ha escrito nada.</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1 with %n problem(s) to repair before it can be computed</source>
        <translation>
            <numerusform>%1 abierto con %n problema que reparar antes de poder calcular</numerusform>
            <numerusform>%1 abierto con %n problemas que reparar antes de poder calcular</numerusform>
        </translation>
    </message>
    <message>
        <source>Computing the report failed: %1</source>
        <translation>El cálculo del informe ha fallado: %1</translation>
    </message>
</context>
<context>
    <name>tolturn::ForceModelEditor</name>
    <message>
        <source>Force model and shop conditions</source>
        <translation>Modelo de fuerzas y condiciones del taller</translation>
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
        <translation>del material</translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation>sin ajustar</translation>
    </message>
    <message>
        <source>not given: 20 °C</source>
        <translation>no indicada: 20 °C</translation>
    </message>
    <message>
        <source>not given: 0 (cold start)</source>
        <translation>no indicado: 0 (arranque en frío)</translation>
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
        <translation>F_f/F_c para el modelo de Kienzle, en lugar de la proporción de los datos del material</translation>
    </message>
    <message>
        <source>F_p/F_c for the Kienzle model, replacing the material data&apos;s ratio</source>
        <translation>F_p/F_c para el modelo de Kienzle, en lugar de la proporción de los datos del material</translation>
    </message>
    <message>
        <source>Ambient temperature of the shop, for the thermal drift (not given: the ISO 1 reference temperature, 20 °C)</source>
        <translation>Temperatura ambiente del taller, para la deriva térmica (no indicada: la temperatura de referencia de ISO 1, 20 °C)</translation>
    </message>
    <message>
        <source>Time since the machine was started, for the thermal warm-up (not given: a cold machine, 0 min)</source>
        <translation>Tiempo desde que se arrancó la máquina, para el calentamiento (no indicado: máquina fría, 0 min)</translation>
    </message>
    <message>
        <source>&amp;Model:</source>
        <translation>&amp;Modelo:</translation>
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
        <translation>Ambiente:</translation>
    </message>
    <message>
        <source>Since start:</source>
        <translation>Desde el arranque:</translation>
    </message>
    <message>
        <source>Kienzle: F_c from kc1.1 and mc of the material, F_f and F_p as ratios of it. Li &amp; Du (2002, eq. 15–20): normal pressure K_n and friction ratio K_f fitted to measured forces (tolturn-cli calibrate-forces).</source>
        <translation>Kienzle: F_c a partir de kc1.1 y mc del material, F_f y F_p como proporciones de ella. Li &amp; Du (2002, ec. 15–20): presión normal K_n y relación de fricción K_f ajustadas a fuerzas medidas (tolturn-cli calibrate-forces).</translation>
    </message>
    <message>
        <source>K_n of Li &amp; Du (2002): normal pressure on the rake face</source>
        <translation>K_n de Li &amp; Du (2002): presión normal sobre la cara de desprendimiento</translation>
    </message>
    <message>
        <source>K_f of Li &amp; Du (2002): friction force over normal force</source>
        <translation>K_f de Li &amp; Du (2002): fuerza de fricción entre fuerza normal</translation>
    </message>
</context>
<context>
    <name>tolturn::HelpBrowser</name>
    <message>
        <source>TolTurn User Guide</source>
        <translation>Guía del usuario de TolTurn</translation>
    </message>
    <message>
        <source>&amp;Contents</source>
        <translation>&amp;Contenido</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Atrás</translation>
    </message>
</context>
<context>
    <name>tolturn::ImportDialog</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: a turned part %2 mm long, Ø max %3 mm, with %4 outer and %5 inner features; %6 warning(s), listed after the import.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: una pieza torneada de %2 mm de longitud, Ø máx. %3 mm, con %4 elementos exteriores y %5 interiores; %6 aviso(s), que se mostrarán tras la importación.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importar %1</translation>
    </message>
    <message>
        <source>Body %1: %2 mm³, %3 faces</source>
        <translation>Cuerpo %1: %2 mm³, %3 caras</translation>
    </message>
    <message>
        <source>Axis %1: through %2 along %3, %4 revolved faces</source>
        <translation>Eje %1: pasa por %2 con dirección %3, %4 caras de revolución</translation>
    </message>
    <message>
        <source>The common axis of the body&apos;s cylindrical, conical, toroidal and spherical faces; the one with the most revolved area is proposed.</source>
        <translation>El eje común de las caras cilíndricas, cónicas, toroidales y esféricas del cuerpo; se propone el de mayor área de revolución.</translation>
    </message>
    <message>
        <source>Chuck at the model&apos;s other end (turn the part end for end)</source>
        <translation>Plato en el otro extremo del modelo (dar la vuelta a la pieza)</translation>
    </message>
    <message>
        <source>z = 0 is the part&apos;s left end, the end held in the chuck. Tick to put the model&apos;s right end there instead.</source>
        <translation>z = 0 es el extremo izquierdo de la pieza, el que se sujeta en el plato. Marque esta opción para situar allí el extremo derecho del modelo.</translation>
    </message>
    <message>
        <source>&amp;Body:</source>
        <translation>&amp;Cuerpo:</translation>
    </message>
    <message>
        <source>&amp;Axis:</source>
        <translation>&amp;Eje:</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>&amp;Importar</translation>
    </message>
</context>
<context>
    <name>tolturn::MainWindow</name>
    <message>
        <source>Open a project (File &gt; Open) or an example part (File &gt; Open Example).</source>
        <translation>Abra un proyecto (Archivo &gt; Abrir) o una pieza de ejemplo (Archivo &gt; Abrir ejemplo).</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Delete Feature</source>
        <translation>&amp;Eliminar elemento</translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation>Preparación</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Tolerancias</translation>
    </message>
    <message>
        <source>Deflection</source>
        <translation>Flexión</translation>
    </message>
    <message>
        <source>Planning</source>
        <translation>Planificación</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>Open &amp;Example</source>
        <translation>Abrir e&amp;jemplo</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Guardar &amp;como…</translation>
    </message>
    <message>
        <source>Export &amp;Report…</source>
        <translation>Exportar &amp;informe…</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>C&amp;errar</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About TolTurn</source>
        <translation>&amp;Acerca de TolTurn</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Acerca de &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation>&amp;Borrar lista</translation>
    </message>
    <message>
        <source>%1[*] — TolTurn</source>
        <translation>%1[*] — TolTurn</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Pieza</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Abrir proyecto</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Guardar proyecto como</translation>
    </message>
    <message>
        <source>Export Report</source>
        <translation>Exportar informe</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>Documentos PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Recuperar cambios sin guardar</translation>
    </message>
    <message>
        <source>TolTurn did not close normally. A copy of %1 with unsaved changes was kept at %2.</source>
        <translation>TolTurn no se cerró correctamente. Se conservó una copia de %1 con cambios sin guardar en %2.</translation>
    </message>
    <message>
        <source>Recover it? A discarded copy is deleted.</source>
        <translation>¿Recuperarla? Si se descarta, la copia se elimina.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Recuperar</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>&amp;Descartar</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation>%1 tiene cambios sin guardar.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>¿Guardarlos antes de continuar?</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>Pre&amp;ferencias…</translation>
    </message>
    <message>
        <source>The new language is used when TolTurn is next started.</source>
        <translation>El nuevo idioma se usará la próxima vez que se inicie TolTurn.</translation>
    </message>
    <message>
        <source>%1 — length %2 %7, Ø max %3 %7, %4 outer / %5 inner features, clamping: %6</source>
        <translation>%1 — longitud %2 %7, Ø máx. %3 %7, %4 elementos exteriores / %5 interiores, sujeción: %6</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barra de herramientas principal</translation>
    </message>
    <message>
        <source>&amp;Fit Part</source>
        <translation>&amp;Encajar pieza</translation>
    </message>
    <message>
        <source>Show the whole part in the drawing (Ctrl+0, or double-click the drawing)</source>
        <translation>Mostrar la pieza entera en el dibujo (Ctrl+0, o doble clic en el dibujo)</translation>
    </message>
    <message>
        <source>&amp;Optimise Cutting Conditions</source>
        <translation>&amp;Optimizar condiciones de corte</translation>
    </message>
    <message>
        <source>Find the cutting conditions that hold every tolerance at least time or cost (F5)</source>
        <translation>Buscar las condiciones de corte que cumplen todas las tolerancias con el mínimo tiempo o coste (F5)</translation>
    </message>
    <message>
        <source>&amp;Import STEP/IGES…</source>
        <translation>I&amp;mportar STEP/IGES…</translation>
    </message>
    <message>
        <source>Read a turned part from a STEP or IGES solid (Ctrl+I)</source>
        <translation>Leer una pieza torneada de un cuerpo STEP o IGES (Ctrl+I)</translation>
    </message>
    <message>
        <source>Export S&amp;TEP…</source>
        <translation>Exportar S&amp;TEP…</translation>
    </message>
    <message>
        <source>Write the part as a solid revolved about its axis (STEP, mm)</source>
        <translation>Escribir la pieza como cuerpo de revolución alrededor de su eje (STEP, mm)</translation>
    </message>
    <message>
        <source>Import Messages</source>
        <translation>Mensajes de importación</translation>
    </message>
    <message>
        <source>No STEP or IGES file imported in this session.</source>
        <translation>No se ha importado ningún archivo STEP o IGES en esta sesión.</translation>
    </message>
    <message>
        <source>Import STEP or IGES</source>
        <translation>Importar STEP o IGES</translation>
    </message>
    <message>
        <source>STEP and IGES files (*.step *.stp *.iges *.igs);;All files (*)</source>
        <translation>Archivos STEP e IGES (*.step *.stp *.iges *.igs);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Export STEP</source>
        <translation>Exportar STEP</translation>
    </message>
    <message>
        <source>STEP files (*.step *.stp)</source>
        <translation>Archivos STEP (*.step *.stp)</translation>
    </message>
    <message>
        <source>Planning &amp;Data…</source>
        <translation>&amp;Datos de planificación…</translation>
    </message>
    <message>
        <source>Rates, tool life, the insert&apos;s cutting ranges and the part&apos;s limits for the optimiser</source>
        <translation>Tarifas, vida de herramienta, rangos de corte de la plaquita y límites de la pieza para el optimizador</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guía del usuario</translation>
    </message>
    <message>
        <source>The user guide, at the page of the dock you are in (F1)</source>
        <translation>La guía del usuario, en la página del panel en el que está (F1)</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problemas</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Mediciones</translation>
    </message>
    <message>
        <source>The set-up shown: its part as held, its deflection, verdicts, plan and program</source>
        <translation>El montaje mostrado: su pieza tal como está sujetada, su flexión, veredictos, plan y programa</translation>
    </message>
    <message>
        <source>%1: %2, %3 end held</source>
        <translation>%1: %2, extremo %3 sujetado</translation>
    </message>
    <message>
        <source>&amp;Operations…</source>
        <translation>&amp;Operaciones…</translation>
    </message>
    <message>
        <source>The set-ups the part is turned in and the features each cuts</source>
        <translation>Los montajes en que se tornea la pieza y los elementos que mecaniza cada uno</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <source>Check with &amp;Solid FE…</source>
        <translation>Comprobar con &amp;sólido FE…</translation>
    </message>
    <message>
        <source>Check the beam&apos;s deflection of the part against a solid model meshed with gmsh and solved with CalculiX</source>
        <translation>Comprobar la flexión de la pieza según la viga con un modelo sólido mallado con gmsh y resuelto con CalculiX</translation>
    </message>
    <message>
        <source>Čuš &amp;&amp; Župerl &amp;End-Milling Example…</source>
        <translation>&amp;Ejemplo de fresado frontal de Čuš &amp;&amp; Župerl…</translation>
    </message>
    <message>
        <source>The constant-force control paper&apos;s own end-milling system rebuilt, beside its results</source>
        <translation>El propio sistema de fresado frontal del artículo de control de fuerza constante reconstruido, junto a sus resultados</translation>
    </message>
    <message>
        <source>Milling</source>
        <translation>Fresado</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasuredPartsModel</name>
    <message>
        <source>Part %1</source>
        <translation>Pieza %1</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Medido</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Pieza</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>By</source>
        <translation>Medido por</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Método</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementEntryDialog</name>
    <message>
        <source>Measured Part — %1 on %2</source>
        <translation>Pieza medida — %1 en %2</translation>
    </message>
    <message>
        <source>micrometer</source>
        <translation>micrómetro</translation>
    </message>
    <message>
        <source>CMM</source>
        <translation>MMC</translation>
    </message>
    <message>
        <source>bore gauge</source>
        <translation>alesómetro</translation>
    </message>
    <message>
        <source>dial gauge along the part</source>
        <translation>reloj comparador a lo largo de la pieza</translation>
    </message>
    <message>
        <source>as in the project</source>
        <translation>como en el proyecto</translation>
    </message>
    <message>
        <source>Minutes from the machine&apos;s start to the cut: the warm-up the thermal error depends on (Li &amp; Du 2022, §3.2).</source>
        <translation>Minutos desde el arranque de la máquina hasta el corte: el calentamiento del que depende el error térmico (Li &amp; Du 2022, §3.2).</translation>
    </message>
    <message>
        <source>Measured &amp;by:</source>
        <translation>Medido &amp;por:</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Método:</translation>
    </message>
    <message>
        <source>Measured &amp;at:</source>
        <translation>Medido &amp;el:</translation>
    </message>
    <message>
        <source>&amp;Time since start [min]:</source>
        <translation>&amp;Tiempo desde el arranque [min]:</translation>
    </message>
    <message>
        <source>Am&amp;bient [°C]:</source>
        <translation>Am&amp;biente [°C]:</translation>
    </message>
    <message>
        <source>&amp;Note:</source>
        <translation>&amp;Nota:</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Medido</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>One measured point a row: a diameter in mm, or a radial deviation in µm (material left on the surface positive).</source>
        <translation>Un punto medido por fila: un diámetro en mm o una desviación radial en µm (positiva si queda material en la superficie).</translation>
    </message>
    <message>
        <source>Add &amp;Row</source>
        <translation>&amp;Añadir fila</translation>
    </message>
    <message>
        <source>&amp;Remove Rows</source>
        <translation>E&amp;liminar filas</translation>
    </message>
    <message>
        <source>Read &amp;CSV…</source>
        <translation>Leer &amp;CSV…</translation>
    </message>
    <message>
        <source>Columns feature, z_mm and diameter_mm or radial_deviation_um (docs/learning.md).</source>
        <translation>Columnas feature, z_mm y diameter_mm o radial_deviation_um (docs/learning.md).</translation>
    </message>
    <message>
        <source>&amp;Store</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>diameter [mm]</source>
        <translation>diámetro [mm]</translation>
    </message>
    <message>
        <source>radial deviation [µm]</source>
        <translation>desviación radial [µm]</translation>
    </message>
    <message>
        <source>Read Measured Points</source>
        <translation>Leer puntos medidos</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>Archivos CSV (*.csv *.txt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>The file was not read:</source>
        <translation>No se ha leído el archivo:</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) read from %1.</source>
        <translation>
            <numerusform>%n punto leído de %1.</numerusform>
            <numerusform>%n puntos leídos de %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>feature</source>
        <translation>elemento</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valor</translation>
    </message>
    <message>
        <source>row %1, %2</source>
        <translation>fila %1, %2</translation>
    </message>
    <message>
        <source>CMM point x; y [mm]</source>
        <translation>Punto de MMC x; y [mm]</translation>
    </message>
</context>
<context>
    <name>tolturn::MeasurementsPanel</name>
    <message>
        <source>Use the &amp;Local Store</source>
        <translation>Usar el almacén &amp;local</translation>
    </message>
    <message>
        <source>Work with the measurement store on this computer until the shop database can be reached again (Preferences keep the shop database).</source>
        <translation>Trabajar con el almacén de mediciones de este equipo hasta que se pueda volver a acceder a la base de datos del taller (las preferencias conservan la base de datos del taller).</translation>
    </message>
    <message>
        <source>This project&apos;s machine</source>
        <translation>Máquina de este proyecto</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>Todas las máquinas</translation>
    </message>
    <message>
        <source>Filter by part, who measured or method</source>
        <translation>Filtrar por pieza, quién midió o método</translation>
    </message>
    <message>
        <source>&amp;Add Measured Part…</source>
        <translation>&amp;Añadir pieza medida…</translation>
    </message>
    <message>
        <source>Type in (or read from CSV) the measured points of a part cut from the open project.</source>
        <translation>Introducir (o leer de CSV) los puntos medidos de una pieza mecanizada según el proyecto abierto.</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Eliminar</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>E&amp;xportar CSV…</translation>
    </message>
    <message>
        <source>What was learned of the machine</source>
        <translation>Lo aprendido de la máquina</translation>
    </message>
    <message>
        <source>L&amp;earn</source>
        <translation>A&amp;prender</translation>
    </message>
    <message>
        <source>Learn the machine&apos;s error beyond the physics from all its measured parts (Li &amp; Du 2022: geometric error by regression, the rest by a hybrid RBF network), check it by leaving one part out, and keep it.</source>
        <translation>Aprender el error de la máquina más allá del modelo físico a partir de todas sus piezas medidas (Li &amp; Du 2022: error geométrico por regresión, el resto con una red RBF híbrida), comprobarlo dejando fuera una pieza cada vez y guardarlo.</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>&amp;Use in the predictions (verdicts, curves, plan, program, report)</source>
        <translation>&amp;Usar en las predicciones (veredictos, curvas, plan, programa, informe)</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Máquina %1</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>Leyendo %1…</translation>
    </message>
    <message>
        <source>of %1</source>
        <translation>de %1</translation>
    </message>
    <message>
        <source>of all machines</source>
        <translation>de todas las máquinas</translation>
    </message>
    <message numerus="yes">
        <source>%n measured part(s) %1 in %2</source>
        <translation>
            <numerusform>%n pieza medida %1 en %2</numerusform>
            <numerusform>%n piezas medidas %1 en %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Open a project to learn its machine from the parts measured on it.</source>
        <translation>Abra un proyecto para aprender su máquina a partir de las piezas mecanizadas y medidas en ella.</translation>
    </message>
    <message>
        <source>Nothing has been learned of %1 yet. Learn needs at least two measured parts; the more parts, conditions and times of day they cover, the better.</source>
        <translation>Aún no se ha aprendido nada de %1. Aprender necesita al menos dos piezas medidas; cuantas más piezas, condiciones y horas del día cubran, mejor.</translation>
    </message>
    <message>
        <source>Model %1, learned %2 from %3 parts (%4 points). Parts not learned from (leave one part out): physics alone %5 µm RMS, physics + learned %6 µm RMS.</source>
        <translation>Modelo %1, aprendido %2 de %3 piezas (%4 puntos). Piezas no aprendidas (dejando una fuera): modelo físico solo %5 µm RMS, modelo físico + aprendido %6 µm RMS.</translation>
    </message>
    <message numerus="yes">
        <source>Part %1 stored with %n point(s).</source>
        <translation>
            <numerusform>Pieza %1 guardada con %n punto.</numerusform>
            <numerusform>Pieza %1 guardada con %n puntos.</numerusform>
        </translation>
    </message>
    <message>
        <source>Measured Part Not Stored</source>
        <translation>Pieza medida no guardada</translation>
    </message>
    <message>
        <source>Remove Measured Parts</source>
        <translation>Eliminar piezas medidas</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n measured part(s) and their points from %1? Models learned before keep what they learned.</source>
        <translation>
            <numerusform>¿Eliminar %n pieza medida y sus puntos de %1? Los modelos aprendidos antes conservan lo que aprendieron.</numerusform>
            <numerusform>¿Eliminar %n piezas medidas y sus puntos de %1? Los modelos aprendidos antes conservan lo que aprendieron.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) removed.</source>
        <translation>
            <numerusform>%n pieza eliminada.</numerusform>
            <numerusform>%n piezas eliminadas.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not Removed</source>
        <translation>No se ha eliminado</translation>
    </message>
    <message>
        <source>Export Measured Parts</source>
        <translation>Exportar piezas medidas</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message numerus="yes">
        <source>%n part(s) written to %1.</source>
        <translation>
            <numerusform>%n pieza escrita en %1.</numerusform>
            <numerusform>%n piezas escritas en %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not Exported</source>
        <translation>No se ha exportado</translation>
    </message>
    <message>
        <source>Learning %1 from its measured parts…</source>
        <translation>Aprendiendo %1 a partir de sus piezas medidas…</translation>
    </message>
    <message>
        <source>Learned and kept as model %1.</source>
        <translation>Aprendido y guardado como modelo %1.</translation>
    </message>
    <message>
        <source>Learning cancelled; the model before is kept.</source>
        <translation>Aprendizaje cancelado; se conserva el modelo anterior.</translation>
    </message>
    <message>
        <source>Nothing learned: %1</source>
        <translation>No se ha aprendido nada: %1</translation>
    </message>
    <message>
        <source>Part %1: measured and predicted radius error</source>
        <translation>Pieza %1: error de radio medido y predicho</translation>
    </message>
    <message>
        <source>z from the part&apos;s left end [%1]</source>
        <translation>z desde el extremo izquierdo de la pieza [%1]</translation>
    </message>
    <message>
        <source>machined − programmed radius [%1]</source>
        <translation>radio mecanizado − programado [%1]</translation>
    </message>
    <message>
        <source>physics</source>
        <translation>modelo físico</translation>
    </message>
    <message>
        <source>physics + learned − %1 µm</source>
        <translation>modelo físico + aprendido − %1 µm</translation>
    </message>
    <message>
        <source>physics + learned + %1 µm</source>
        <translation>modelo físico + aprendido + %1 µm</translation>
    </message>
    <message>
        <source>physics + learned</source>
        <translation>modelo físico + aprendido</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message numerus="yes">
        <source>Measured %1 by %2 (%3), %n point(s) compared.</source>
        <translation>
            <numerusform>Medida %1 por %2 (%3), %n punto comparado.</numerusform>
            <numerusform>Medida %1 por %2 (%3), %n puntos comparados.</numerusform>
        </translation>
    </message>
    <message>
        <source>No model of %1 to compare with: Learn, then select the part again.</source>
        <translation>No hay modelo de %1 con el que comparar: use «Aprender» y vuelva a seleccionar la pieza.</translation>
    </message>
    <message>
        <source>the store or the machine changed meanwhile; the model was kept in %1</source>
        <translation>el almacén o la máquina cambiaron entretanto; el modelo se guardó en %1</translation>
    </message>
    <message>
        <source>Learned at %1.</source>
        <translation>Aprendido con %1.</translation>
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
        <translation>planitud</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>perfil</translation>
    </message>
    <message>
        <source>not evaluated: lacks %1</source>
        <translation>no evaluado: sin %1</translation>
    </message>
    <message>
        <source>not evaluated: %1</source>
        <translation>no evaluado: %1</translation>
    </message>
    <message>
        <source>passes, %1 of %2 µm</source>
        <translation>cumple, %1 de %2 µm</translation>
    </message>
    <message>
        <source>fails, %1 of %2 µm</source>
        <translation>no cumple, %1 de %2 µm</translation>
    </message>
    <message>
        <source>Milled features of the part</source>
        <translation>Elementos fresados de la pieza</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>z [mm]</source>
        <translation>z [mm]</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>where the cutting coefficients come from</source>
        <translation>de dónde proceden los coeficientes de corte</translation>
    </message>
    <message>
        <source>Add Cut as Feature</source>
        <translation>Añadir corte como elemento</translation>
    </message>
    <message>
        <source>Save Cut to Feature</source>
        <translation>Guardar corte en el elemento</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>z from, to</source>
        <translation>z desde, hasta</translation>
    </message>
    <message>
        <source>Coefficients from</source>
        <translation>Fuente de los coeficientes</translation>
    </message>
    <message>
        <source>along the path [mm]</source>
        <translation>a lo largo de la trayectoria [mm]</translation>
    </message>
    <message>
        <source>surface-normal error [µm]</source>
        <translation>error normal a la superficie [µm]</translation>
    </message>
    <message>
        <source>evaluating…</source>
        <translation>evaluando…</translation>
    </message>
    <message>
        <source>Choose an evaluated feature</source>
        <translation>Elija un elemento evaluado</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>δ_N least</source>
        <translation>δ_N mínimo</translation>
    </message>
    <message>
        <source>δ_N over a revolution</source>
        <translation>δ_N durante una vuelta</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>zona, inferior</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>zona, superior</translation>
    </message>
    <message>
        <source>Add milled feature %1</source>
        <translation>Añadir elemento fresado %1</translation>
    </message>
    <message>
        <source>Choose the feature to save the cut to.</source>
        <translation>Elija el elemento en el que guardar el corte.</translation>
    </message>
    <message>
        <source>Change milled feature %1</source>
        <translation>Cambiar elemento fresado %1</translation>
    </message>
    <message>
        <source>Choose the feature to remove.</source>
        <translation>Elija el elemento que quitar.</translation>
    </message>
    <message>
        <source>Remove milled feature %1</source>
        <translation>Quitar elemento fresado %1</translation>
    </message>
    <message>
        <source>Evaluating…</source>
        <translation>Evaluando…</translation>
    </message>
    <message>
        <source>Coefficients from: &quot;%1&quot; is given but there are no coefficients (Ktc, Krc, Kac, Kte, Kre, Kae) to go with it; enter them, or clear the field.</source>
        <translation>Fuente de los coeficientes: se indica «%1», pero no hay coeficientes (Ktc, Krc, Kac, Kte, Kre, Kae) a los que corresponda; introdúzcalos o vacíe el campo.</translation>
    </message>
</context>
<context>
    <name>tolturn::MillingPanel</name>
    <message>
        <source>Ball-end cut</source>
        <translation>Corte con fresa de punta esférica</translation>
    </message>
    <message>
        <source>Öztürk &amp; Budak, case %1</source>
        <translation>Öztürk &amp; Budak, caso %1</translation>
    </message>
    <message>
        <source>Own cut</source>
        <translation>Corte propio</translation>
    </message>
    <message>
        <source>001 table 4: a DMU 50 Evolution, Ø12 mm ball-end mills with a 30° helix, Ti6Al4V</source>
        <translation>001 tabla 4: una DMU 50 Evolution, fresas de punta esférica de Ø12 mm con hélice de 30°, Ti6Al4V</translation>
    </message>
    <message>
        <source>Example</source>
        <translation>Ejemplo</translation>
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
        <translation>Ranura</translation>
    </message>
    <message>
        <source>Side cut (uncut material)</source>
        <translation>Corte lateral (material sin cortar)</translation>
    </message>
    <message>
        <source>Step-over (beside a pass)</source>
        <translation>Paso lateral (junto a una pasada)</translation>
    </message>
    <message>
        <source>Down milling</source>
        <translation>Fresado en concordancia</translation>
    </message>
    <message>
        <source>Up milling</source>
        <translation>Fresado en oposición</translation>
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
        <translation>Los coeficientes de corte y de filo de su herramienta y material (001 ec. 11). 001 no publica ninguno y la biblioteca de datos de TolTurn no tiene ninguno para fresado con fresa de punta esférica.</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Diámetro</translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation>Filos</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Hélice</translation>
    </message>
    <message>
        <source>Lead</source>
        <translation>Lead</translation>
    </message>
    <message>
        <source>Tilt</source>
        <translation>Tilt</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Corte</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Sentido</translation>
    </message>
    <message>
        <source>Radial depth / step-over</source>
        <translation>Profundidad radial / paso lateral</translation>
    </message>
    <message>
        <source>Axial depth</source>
        <translation>Profundidad axial</translation>
    </message>
    <message>
        <source>Feed per tooth</source>
        <translation>Avance por diente</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Velocidad del husillo</translation>
    </message>
    <message>
        <source>Coefficients</source>
        <translation>Coeficientes</translation>
    </message>
    <message>
        <source>Tool structure and tolerance</source>
        <translation>Estructura de la herramienta y tolerancia</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>no indicado</translation>
    </message>
    <message>
        <source>From where the holder grips the tool to its tip</source>
        <translation>Desde donde el portaherramientas sujeta la herramienta hasta su punta</translation>
    </message>
    <message>
        <source>The diameter of the solid cylinder that bends like the fluted tool</source>
        <translation>El diámetro del cilindro macizo que se flexiona como la herramienta con ranuras</translation>
    </message>
    <message>
        <source> N/mm²</source>
        <translation> N/mm²</translation>
    </message>
    <message>
        <source>Tungsten carbide 630 000 N/mm² (MakeItFrom); cemented carbides 530 000–700 000</source>
        <translation>Carburo de wolframio 630 000 N/mm² (MakeItFrom); metales duros 530 000–700 000</translation>
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
        <translation>Perfil con referencias (±t/2)</translation>
    </message>
    <message>
        <source>The largest feed per tooth the tool&apos;s maker allows</source>
        <translation>El mayor avance por diente que permite el fabricante de la herramienta</translation>
    </message>
    <message>
        <source>Plan Lead, Tilt and Feed</source>
        <translation>Planificar lead, tilt y avance</translation>
    </message>
    <message>
        <source>Overhang</source>
        <translation>Voladizo</translation>
    </message>
    <message>
        <source>Equivalent diameter</source>
        <translation>Diámetro equivalente</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>Módulo de Young</translation>
    </message>
    <message>
        <source>Holder k</source>
        <translation>Portaherramientas k</translation>
    </message>
    <message>
        <source>Holder k_θ</source>
        <translation>Portaherramientas k_θ</translation>
    </message>
    <message>
        <source>Surface tolerance t</source>
        <translation>Tolerancia de superficie t</translation>
    </message>
    <message>
        <source>Zone</source>
        <translation>Zona</translation>
    </message>
    <message>
        <source>Largest feed per tooth</source>
        <translation>Mayor avance por diente</translation>
    </message>
    <message>
        <source>Holder springs: as entered.</source>
        <translation>Resortes del portaherramientas: según lo introducido.</translation>
    </message>
    <message>
        <source>rotation angle [°]</source>
        <translation>ángulo de rotación [°]</translation>
    </message>
    <message>
        <source>force on the tool [N]</source>
        <translation>fuerza sobre la herramienta [N]</translation>
    </message>
    <message>
        <source>surface-normal error [µm]</source>
        <translation>error normal a la superficie [µm]</translation>
    </message>
    <message>
        <source>lead [°]</source>
        <translation>lead [°]</translation>
    </message>
    <message>
        <source>tilt [°]</source>
        <translation>tilt [°]</translation>
    </message>
    <message>
        <source>Plan to see the largest feed per tooth that holds the tolerance at each lead and tilt.</source>
        <translation>Planifique para ver el mayor avance por diente que cumple la tolerancia con cada lead y tilt.</translation>
    </message>
    <message>
        <source>Forces</source>
        <translation>Fuerzas</translation>
    </message>
    <message>
        <source>Surface error</source>
        <translation>Error de superficie</translation>
    </message>
    <message>
        <source>Lead–tilt window</source>
        <translation>Ventana lead–tilt</translation>
    </message>
    <message>
        <source>Holder springs: 001&apos;s calibration for its Ø12 mm tool and holder, under 1000 N.</source>
        <translation>Resortes del portaherramientas: calibración de 001 para su herramienta de Ø12 mm y su portaherramientas, por debajo de 1000 N.</translation>
    </message>
    <message>
        <source>Coefficients: not given. Enter Ktc, Krc, Kac, Kte, Kre, Kae of your tool and material: Öztürk &amp; Budak print none (theirs come from a Ti6Al4V orthogonal-cutting database), and TolTurn&apos;s data library has none for ball-end milling.</source>
        <translation>Coeficientes: no indicados. Introduzca Ktc, Krc, Kac, Kte, Kre, Kae de su herramienta y material: Öztürk &amp; Budak no publican ninguno (los suyos vienen de una base de datos de corte ortogonal de Ti6Al4V) y la biblioteca de datos de TolTurn no tiene ninguno para fresado con fresa de punta esférica.</translation>
    </message>
    <message>
        <source>Coefficients: &quot;%1&quot; is not six numbers of at most 100 000.</source>
        <translation>Coeficientes: «%1» no son seis números de como mucho 100 000.</translation>
    </message>
    <message>
        <source>No surface error: %1</source>
        <translation>Sin error de superficie: %1</translation>
    </message>
    <message>
        <source>F (feed)</source>
        <translation>F (avance)</translation>
    </message>
    <message>
        <source>C (cross-feed)</source>
        <translation>C (transversal)</translation>
    </message>
    <message>
        <source>N (normal)</source>
        <translation>N (normal)</translation>
    </message>
    <message>
        <source>resultant</source>
        <translation>resultante</translation>
    </message>
    <message>
        <source>Peak resultant %1 N; mean torque %2 N·m, mean spindle power %3 W. Coefficients as entered; only the tool deflects (001 §4).</source>
        <translation>Resultante máxima %1 N; par medio %2 N·m, potencia media del husillo %3 W. Coeficientes según lo introducido; solo se flexiona la herramienta (001 §4).</translation>
    </message>
    <message>
        <source>δ_N</source>
        <translation>δ_N</translation>
    </message>
    <message>
        <source>zone, lower</source>
        <translation>zona, inferior</translation>
    </message>
    <message>
        <source>zone, upper</source>
        <translation>zona, superior</translation>
    </message>
    <message>
        <source>&lt;b&gt;passes&lt;/b&gt; by %1 µm</source>
        <translation>&lt;b&gt;cumple&lt;/b&gt; con %1 µm de margen</translation>
    </message>
    <message>
        <source>&lt;b&gt;fails&lt;/b&gt; by %1 µm</source>
        <translation>&lt;b&gt;no cumple&lt;/b&gt; por %1 µm</translation>
    </message>
    <message>
        <source>&lt;br&gt;Surface-normal error %1 to %2 µm over a revolution; against t = %3 µm (%4) it %5.</source>
        <translation>&lt;br&gt;Error normal a la superficie de %1 a %2 µm durante una vuelta; frente a t = %3 µm (%4): %5.</translation>
    </message>
    <message>
        <source>spread</source>
        <translation>dispersión</translation>
    </message>
    <message>
        <source>±t/2</source>
        <translation>±t/2</translation>
    </message>
    <message>
        <source>Planning: 64 × 64 leads and tilts…</source>
        <translation>Planificando: 64 × 64 ángulos lead y tilt…</translation>
    </message>
    <message>
        <source>plan</source>
        <translation>plan</translation>
    </message>
    <message>
        <source>as entered</source>
        <translation>según lo introducido</translation>
    </message>
    <message>
        <source>Lighter: a larger feed per tooth holds the tolerance; red: none does; grey: the cut would reach the shank above the ball.</source>
        <translation>Más claro: un mayor avance por diente cumple la tolerancia; rojo: ninguno; gris: el corte alcanzaría el mango por encima de la bola.</translation>
    </message>
    <message>
        <source>Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min), form error %5 µm. %6</source>
        <translation>Plan: lead %1°, tilt %2°, avance %3 mm/diente (%4 mm/min), error de forma %5 µm. %6</translation>
    </message>
    <message>
        <source>No lead and tilt within ±40° holds the tolerance at any feed. %1</source>
        <translation>Ningún lead ni tilt dentro de ±40° cumple la tolerancia con ningún avance. %1</translation>
    </message>
    <message>
        <source>give the tool&apos;s overhang</source>
        <translation>indique el voladizo de la herramienta</translation>
    </message>
    <message>
        <source>give the tool&apos;s equivalent diameter</source>
        <translation>indique el diámetro equivalente de la herramienta</translation>
    </message>
    <message>
        <source>No plan: %1</source>
        <translation>Sin plan: %1</translation>
    </message>
    <message>
        <source>The inputs have changed since this plan: plan again.</source>
        <translation>Los datos han cambiado desde este plan: vuelva a planificar.</translation>
    </message>
    <message>
        <source>Flatness</source>
        <translation>Planitud</translation>
    </message>
    <message>
        <source>Profile without datums</source>
        <translation>Perfil sin referencias</translation>
    </message>
    <message>
        <source>ISO 1101: a flatness and a profile without datums float (the spread within t); a profile with datums is located on the programmed surface (within ±t/2)</source>
        <translation>ISO 1101: una planitud y un perfil sin referencias son flotantes (la dispersión dentro de t); un perfil con referencias está situado sobre la superficie programada (dentro de ±t/2)</translation>
    </message>
    <message>
        <source>Along the path</source>
        <translation>A lo largo de la trayectoria</translation>
    </message>
    <message>
        <source>Holder springs: feature %1&apos;s.</source>
        <translation>Resortes del portaherramientas: los del elemento %1.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 lacks %2&lt;/b&gt;: the fields show the last cut; save the cut to the feature to give it these.</source>
        <translation>&lt;b&gt;%1 no tiene %2&lt;/b&gt;: los campos muestran el último corte; guarde el corte en el elemento para asignárselos.</translation>
    </message>
    <message>
        <source>&lt;br&gt;A patch&apos;s lead and tilt come from its path, point by point (Along the path); the fields show its conditions&apos; own.</source>
        <translation>&lt;br&gt;El lead y el tilt de un parche vienen de su trayectoria, punto por punto (A lo largo de la trayectoria); los campos muestran los de sus propias condiciones.</translation>
    </message>
    <message>
        <source>A, B</source>
        <translation>A, B</translation>
    </message>
    <message>
        <source>Datums</source>
        <translation>Referencias</translation>
    </message>
    <message>
        <source>Feature %1 has no holder springs: these are the last cut&apos;s, and saving the cut gives them to it.</source>
        <translation>El elemento %1 no tiene muelles del portaherramientas: estos son los del último corte, y guardar el corte se los da.</translation>
    </message>
    <message>
        <source>Coefficients: &quot;%1&quot; is not six numbers; the feature is left as it was.</source>
        <translation>Coeficientes: «%1» no son seis números; el elemento queda como estaba.</translation>
    </message>
    <message>
        <source>A profile with datums needs its datums (A, B).</source>
        <translation>Un perfil con referencias necesita sus referencias (A, B).</translation>
    </message>
    <message>
        <source>Beyond 001:</source>
        <translation>Fuera de 001:</translation>
    </message>
    <message>
        <source>Beyond 001: %1</source>
        <translation>Fuera de 001: %1</translation>
    </message>
</context>
<context>
    <name>tolturn::OperationsDialog</name>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Quitar</translation>
    </message>
    <message>
        <source>Operations</source>
        <translation>Operaciones</translation>
    </message>
    <message>
        <source>&amp;Add Operation</source>
        <translation>&amp;Añadir operación</translation>
    </message>
    <message>
        <source>A set-up after the others: the part turned end for end in the chuck, with this project&apos;s tool and passes; tick the features it cuts</source>
        <translation>Un montaje tras los demás: la pieza volteada en el plato, con la herramienta y las pasadas de este proyecto; marque los elementos que mecaniza</translation>
    </message>
    <message>
        <source>Set-ups, in order:</source>
        <translation>Montajes, en orden:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>Features it cuts (the first set-up cuts every feature no other ticks):</source>
        <translation>Elementos que mecaniza (el primer montaje mecaniza todo elemento que ningún otro marca):</translation>
    </message>
    <message>
        <source>Clamping, tools and passes of each set-up are edited in the Set-up dock with the set-up chosen in the toolbar (docs/operations.md).</source>
        <translation>La sujeción, las herramientas y las pasadas de cada montaje se editan en el panel de preparación con el montaje elegido en la barra de herramientas (docs/operations.md).</translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningDataDialog</name>
    <message>
        <source>Planning Data</source>
        <translation>Datos de planificación</translation>
    </message>
    <message>
        <source>What the optimiser works with (docs/planning.md). A box showing “—” is not given.</source>
        <translation>Con qué trabaja el optimizador (docs/planning.md). Un campo con «—» no está indicado.</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Rates and times</source>
        <translation>Tarifas y tiempos</translation>
    </message>
    <message>
        <source>Cost per part C = M·t + C_edge·edges (docs/planning.md §1); in the currency of your choice, the same for both rates.</source>
        <translation>Coste por pieza C = M·t + C_filo·filos (docs/planning.md §1); en la moneda que elija, la misma para ambas tarifas.</translation>
    </message>
    <message>
        <source>&amp;Machine and operator rate:</source>
        <translation>Tarifa de &amp;máquina y operario:</translation>
    </message>
    <message>
        <source>per min</source>
        <translation>por min</translation>
    </message>
    <message>
        <source>Tool cost per &amp;edge:</source>
        <translation>Coste de herramienta por &amp;filo:</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>Time to index or change the cutting edge, t_change (docs/planning.md §1).</source>
        <translation>Tiempo para girar o cambiar el filo, t_change (docs/planning.md §1).</translation>
    </message>
    <message>
        <source>&amp;Handling time per part:</source>
        <translation>Tiempo de &amp;manipulación por pieza:</translation>
    </message>
    <message>
        <source>Loading, unloading and idle moves per part, t_handling (docs/planning.md §1).</source>
        <translation>Carga, descarga y movimientos en vacío por pieza, t_handling (docs/planning.md §1).</translation>
    </message>
    <message>
        <source>Tool life (Taylor: v·Tⁿ = C)</source>
        <translation>Vida de herramienta (Taylor: v·Tⁿ = C)</translation>
    </message>
    <message>
        <source>Taylor (1907): v·Tⁿ = C with v in m/min and T in min; give both C and n, from the insert maker or your own tool-life tests, with their source. Without them tool life is left out of the plan.</source>
        <translation>Taylor (1907): v·Tⁿ = C con v en m/min y T en min; indique C y n juntos, del fabricante de la plaquita o de sus propios ensayos de vida, con su fuente. Sin ellos la vida de herramienta queda fuera del plan.</translation>
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
        <translation>&amp;Vida mínima de herramienta:</translation>
    </message>
    <message>
        <source>The tool_life constraint: T(v) at least this (docs/planning.md §2).</source>
        <translation>La restricción tool_life: T(v) al menos este valor (docs/planning.md §2).</translation>
    </message>
    <message>
        <source>where C and n come from</source>
        <translation>de dónde proceden C y n</translation>
    </message>
    <message>
        <source>&amp;Source:</source>
        <translation>&amp;Fuente:</translation>
    </message>
    <message>
        <source>From the Material&apos;s Data</source>
        <translation>De los datos del material</translation>
    </message>
    <message>
        <source>Fill C, n and the source from the data of %1.</source>
        <translation>Rellenar C, n y la fuente con los datos de %1.</translation>
    </message>
    <message>
        <source>The data of %1 gives no Taylor constants.</source>
        <translation>Los datos de %1 no incluyen constantes de Taylor.</translation>
    </message>
    <message>
        <source>%1 (material %2): C from %3; n from %4</source>
        <translation>%1 (material %2): C de %3; n de %4</translation>
    </message>
    <message>
        <source>TolTurn material data</source>
        <translation>datos de materiales de TolTurn</translation>
    </message>
    <message>
        <source>Cutting ranges of the insert</source>
        <translation>Rangos de corte de la plaquita</translation>
    </message>
    <message>
        <source>The insert maker&apos;s recommended range (catalogue), the bounds of the optimiser&apos;s variables (docs/planning.md §2–3).</source>
        <translation>El rango recomendado por el fabricante de la plaquita (catálogo), los límites de las variables del optimizador (docs/planning.md §2–3).</translation>
    </message>
    <message>
        <source>&amp;Feed:</source>
        <translation>&amp;Avance:</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/rev</translation>
    </message>
    <message>
        <source>&amp;Depth of cut:</source>
        <translation>&amp;Profundidad de corte:</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>catalogue, page, chip breaker</source>
        <translation>catálogo, página, rompevirutas</translation>
    </message>
    <message>
        <source>S&amp;ource:</source>
        <translation>F&amp;uente:</translation>
    </message>
    <message>
        <source>Requirements and limits</source>
        <translation>Requisitos y límites</translation>
    </message>
    <message>
        <source> “—”: the machine&apos;s limit from its data, if it has one.</source>
        <translation> «—»: el límite de la máquina según sus datos, si lo tiene.</translation>
    </message>
    <message>
        <source>Max. &amp;Ra:</source>
        <translation>&amp;Ra máx.:</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>Theoretical roughness Ra = f²/(32·rε) of the finishing pass.</source>
        <translation>Rugosidad teórica Ra = f²/(32·rε) de la pasada de acabado.</translation>
    </message>
    <message>
        <source>Max. R&amp;z:</source>
        <translation>R&amp;z máx.:</translation>
    </message>
    <message>
        <source>Theoretical roughness Rz = f²/(8·rε) of the finishing pass.</source>
        <translation>Rugosidad teórica Rz = f²/(8·rε) de la pasada de acabado.</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>Upper limit of the cutting force F_c.</source>
        <translation>Límite superior de la fuerza de corte F_c.</translation>
    </message>
    <message>
        <source>kW</source>
        <translation>kW</translation>
    </message>
    <message>
        <source>Spindle power F_c·v available.</source>
        <translation>Potencia de husillo disponible F_c·v.</translation>
    </message>
    <message>
        <source>N·m</source>
        <translation>N·m</translation>
    </message>
    <message>
        <source>Spindle torque F_c·D/2 available.</source>
        <translation>Par de husillo disponible F_c·D/2.</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>rpm</translation>
    </message>
    <message>
        <source>Tool change &amp;time:</source>
        <translation>&amp;Tiempo de cambio de herramienta:</translation>
    </message>
    <message>
        <source>Cutting s&amp;peed:</source>
        <translation>Veloc&amp;idad de corte:</translation>
    </message>
    <message>
        <source>Ma&amp;x. cutting force:</source>
        <translation>&amp;Fuerza de corte máx.:</translation>
    </message>
    <message>
        <source>Max. po&amp;wer:</source>
        <translation>&amp;Potencia máx.:</translation>
    </message>
    <message>
        <source>Max. tor&amp;que:</source>
        <translation>Par de &amp;giro máx.:</translation>
    </message>
    <message>
        <source>Max. sp&amp;indle speed:</source>
        <translation>Velocidad de &amp;husillo máx.:</translation>
    </message>
    <message>
        <source>Derive C</source>
        <translation>Derivar C</translation>
    </message>
    <message>
        <source>The speed the insert&apos;s catalogue recommends and the tool life it states for it (often 15 min): C = v·Tⁿ, with n from tool makers&apos; speed–life factors.</source>
        <translation>La velocidad que recomienda el catálogo de la plaquita y la vida de herramienta que indica para ella (a menudo 15 min): C = v·Tⁿ, con n de los factores velocidad–vida de los fabricantes de herramientas.</translation>
    </message>
    <message>
        <source>at</source>
        <translation>a</translation>
    </message>
    <message>
        <source>Catalogue speed:</source>
        <translation>Velocidad de catálogo:</translation>
    </message>
    <message>
        <source>Catalogue speed: give the recommended speed and the tool life the catalogue states for it.</source>
        <translation>Velocidad de catálogo: indique la velocidad recomendada y la vida de herramienta que el catálogo da para ella.</translation>
    </message>
    <message>
        <source>C = %1 m/min x %2 min^%3 from the insert catalogue&apos;s recommended speed; n: %4</source>
        <translation>C = %1 m/min x %2 min^%3 a partir de la velocidad recomendada del catálogo de la plaquita; n: %4</translation>
    </message>
    <message>
        <source>Highest spindle speed: the program clamps constant surface speed at it.</source>
        <translation>Velocidad máxima del husillo: el programa limita a ella la velocidad de corte constante.</translation>
    </message>
</context>
<context>
    <name>tolturn::PlanningPanel</name>
    <message>
        <source>Optimise</source>
        <translation>Optimizar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Apply to Passes</source>
        <translation>Aplicar a las pasadas</translation>
    </message>
    <message>
        <source>Compensated</source>
        <translation>Compensado</translation>
    </message>
    <message>
        <source>Export G-code…</source>
        <translation>Exportar código G…</translation>
    </message>
    <message>
        <source>Least time per part</source>
        <translation>Mínimo tiempo por pieza</translation>
    </message>
    <message>
        <source>Least cost per part</source>
        <translation>Mínimo coste por pieza</translation>
    </message>
    <message>
        <source>Window: feed – cutting speed</source>
        <translation>Ventana: avance – velocidad de corte</translation>
    </message>
    <message>
        <source>Window: feed – depth of cut</source>
        <translation>Ventana: avance – profundidad de corte</translation>
    </message>
    <message>
        <source>Constraints:</source>
        <translation>Restricciones:</translation>
    </message>
    <message>
        <source>Switch the %1 constraint on or off (docs/planning.md §2)</source>
        <translation>Activar o desactivar la restricción %1 (docs/planning.md §2)</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>Posición</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Sujeción</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Tolerances</source>
        <translation>Tolerancias</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Acción</translation>
    </message>
    <message>
        <source>Offset Ø [µm]</source>
        <translation>Corrección Ø [µm]</translation>
    </message>
    <message>
        <source>Residual before [µm]</source>
        <translation>Residuo antes [µm]</translation>
    </message>
    <message>
        <source>Residual after [µm]</source>
        <translation>Residuo después [µm]</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <source>Cutting Window</source>
        <translation>Ventana de corte</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>Compensación</translation>
    </message>
    <message>
        <source>G-code</source>
        <translation>Código G</translation>
    </message>
    <message>
        <source>Export G-code</source>
        <translation>Exportar código G</translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.tap);;All files (*)</source>
        <translation>Código G (*.nc *.ngc *.tap);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Apply optimal passes</source>
        <translation>Aplicar pasadas óptimas</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Cancelado.</translation>
    </message>
    <message>
        <source>Optimal plan</source>
        <translation>Plan óptimo</translation>
    </message>
    <message>
        <source>No plan meets every constraint; the least-violating one:</source>
        <translation>Ningún plan cumple todas las restricciones; el que menos las incumple:</translation>
    </message>
    <message>
        <source>Finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm</source>
        <translation>Acabado: vc %1 m/min, f %2 mm/rev, ap %3 mm</translation>
    </message>
    <message>
        <source>Binding: %1 (%2 of %3 %4)</source>
        <translation>Restricción activa: %1 (%2 de %3 %4)</translation>
    </message>
    <message>
        <source>Note: </source>
        <translation>Nota: </translation>
    </message>
    <message>
        <source>&lt;b&gt;Green&lt;/b&gt;: feasible, darker is better.</source>
        <translation>&lt;b&gt;Verde&lt;/b&gt;: factible; cuanto más oscuro, mejor.</translation>
    </message>
    <message>
        <source>optimum</source>
        <translation>óptimo</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – cutting speed</source>
        <translation>Ventana de corte de la pasada de acabado: avance – velocidad de corte</translation>
    </message>
    <message>
        <source>Cutting window of the finishing pass: feed – depth of cut</source>
        <translation>Ventana de corte de la pasada de acabado: avance – profundidad de corte</translation>
    </message>
    <message>
        <source>feed f [mm/rev]</source>
        <translation>avance f [mm/rev]</translation>
    </message>
    <message>
        <source>cutting speed vc [m/min]</source>
        <translation>velocidad de corte vc [m/min]</translation>
    </message>
    <message>
        <source>depth of cut ap [mm]</source>
        <translation>profundidad de corte ap [mm]</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>constant offset</source>
        <translation>corrección constante</translation>
    </message>
    <message>
        <source>profile correction</source>
        <translation>corrección del perfil</translation>
    </message>
    <message>
        <source>Planning Data…</source>
        <translation>Datos de planificación…</translation>
    </message>
    <message>
        <source>Rates, tool life, the insert&apos;s cutting ranges and the part&apos;s limits the optimiser works with</source>
        <translation>Tarifas, vida de herramienta, rangos de corte de la plaquita y límites de la pieza con los que trabaja el optimizador</translation>
    </message>
    <message>
        <source>%1: no limit known</source>
        <translation>%1: sin límite conocido</translation>
    </message>
    <message>
        <source>No %1 limit is known for this machine and project: it is not checked. Enter one in Planning Data….</source>
        <translation>No se conoce ningún límite de %1 para esta máquina y proyecto: no se comprueba. Introduzca uno en Datos de planificación….</translation>
    </message>
    <message>
        <source>Machine&apos;s control</source>
        <translation>Control de la máquina</translation>
    </message>
    <message>
        <source>The control the program is written for</source>
        <translation>El control para el que se escribe el programa</translation>
    </message>
    <message>
        <source>Nose radius: G41/G42 by the control</source>
        <translation>Radio de punta: G41/G42 por el control</translation>
    </message>
    <message>
        <source>Nose radius: tip path by TolTurn</source>
        <translation>Radio de punta: trayectoria de la punta por TolTurn</translation>
    </message>
    <message>
        <source>G42: the program is the contour and the control offsets it by the nose radius in its tool data. Tip path: TolTurn offsets it, for controls without compensation.</source>
        <translation>G42: el programa es el contorno y el control lo desplaza con el radio de punta de sus datos de herramienta. Trayectoria de la punta: la desplaza TolTurn, para controles sin compensación.</translation>
    </message>
    <message>
        <source>Not optimised yet. Press F5 (or Optimise) to find the cutting conditions that hold every tolerance at least time or cost; the cutting window, the clamping ranking and the compensation follow. Planning Data… holds the rates, tool life and the insert&apos;s ranges the optimiser works with.</source>
        <translation>Aún sin optimizar. Pulse F5 (u Optimizar) para hallar las condiciones de corte que cumplen todas las tolerancias con el mínimo tiempo o coste; siguen la ventana de corte, la clasificación de sujeciones y la compensación. Datos de planificación… contiene las tarifas, la vida de la herramienta y los rangos de la plaquita con los que trabaja el optimizador.</translation>
    </message>
    <message>
        <source>programmed</source>
        <translation>programado</translation>
    </message>
    <message>
        <source>programmed (f %1 mm/rev, %2 %3) lies outside this window</source>
        <translation>programado (f %1 mm/rev, %2 %3) queda fuera de esta ventana</translation>
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
        <translation>Pasada</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>n [rpm]</source>
        <translation>n [rpm]</translation>
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
        <source>Power [kW]</source>
        <translation>Potencia [kW]</translation>
    </message>
    <message>
        <source>Time [min]</source>
        <translation>Tiempo [min]</translation>
    </message>
    <message>
        <source>The optimal passes as the program would cut them: the spindle speed range under G96 and the spindle limit, the cutting power Fc·vc and the time along the tool path</source>
        <translation>Las pasadas óptimas tal como las cortaría el programa: el rango de velocidad del husillo con G96 y su límite, la potencia de corte Fc·vc y el tiempo a lo largo de la trayectoria</translation>
    </message>
    <message>
        <source>%1 (no currency set in Preferences)</source>
        <translation>%1 (sin moneda en las preferencias)</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>The project has problems (listed under Problems): nothing is planned or programmed until they are repaired.</source>
        <translation>El proyecto tiene problemas (listados en Problemas): no se planifica ni se programa nada hasta repararlos.</translation>
    </message>
    <message>
        <source>Make These Operations</source>
        <translation>Crear estas operaciones</translation>
    </message>
    <message>
        <source>Add the proposed set-up to the project (undoable); Edit &gt; Operations… changes it</source>
        <translation>Añadir el montaje propuesto al proyecto (se puede deshacer); Editar &gt; Operaciones… lo cambia</translation>
    </message>
    <message>
        <source>Split into operations: %1.</source>
        <translation>Dividir en operaciones: %1.</translation>
    </message>
    <message>
        <source>Feed schedule</source>
        <translation>Programa de avances</translation>
    </message>
    <message>
        <source>Adaptive</source>
        <translation>Adaptativo</translation>
    </message>
    <message>
        <source>Cut each feature of the finishing pass at its feed of the Adaptive tab&apos;s schedule (compensated too: the features no feed holds keep the programmed feed and are compensated at it)</source>
        <translation>Mecanizar cada elemento de la pasada de acabado con su avance del plan de la pestaña Adaptativo (también compensado: los elementos que ningún avance cumple conservan el avance programado y se compensan con él)</translation>
    </message>
    <message>
        <source>The optimisation failed: %1</source>
        <translation>La optimización ha fallado: %1</translation>
    </message>
    <message>
        <source>Violated: %1 %2</source>
        <translation>Restricción incumplida: %1 %2</translation>
    </message>
    <message>
        <source>To meet it: </source>
        <translation>Para cumplirla: </translation>
    </message>
    <message numerus="yes">
        <source>Roughing: %n pass(es) at vc %1 m/min, f %2 mm/rev</source>
        <translation>
            <numerusform>Desbaste: %n pasada a vc %1 m/min, f %2 mm/rev</numerusform>
            <numerusform>Desbaste: %n pasadas a vc %1 m/min, f %2 mm/rev</numerusform>
        </translation>
    </message>
    <message>
        <source>tool edges %1 per part</source>
        <translation>filos de herramienta %1 por pieza</translation>
    </message>
    <message>
        <source>tool edges not known (no tool life)</source>
        <translation>filos de herramienta desconocidos (sin vida de herramienta)</translation>
    </message>
    <message>
        <source>Time per part %1 min (finishing %2 min, roughing %3 min, handling %4 min, tool changes %5); cost %6; %7</source>
        <translation>Tiempo por pieza %1 min (acabado %2 min, desbaste %3 min, manipulación %4 min, cambios de herramienta %5); coste %6; %7</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>desconocido</translation>
    </message>
    <message>
        <source>The project&apos;s passes: %1. Dialect: %2. Program %3, checksum %4.</source>
        <translation>Las pasadas del proyecto: %1. Dialecto: %2. Programa %3, suma de control %4.</translation>
    </message>
</context>
<context>
    <name>tolturn::ProblemNavigator</name>
    <message>
        <source>No problems: every value of the project can be computed with.</source>
        <translation>Sin problemas: todos los valores del proyecto se pueden calcular.</translation>
    </message>
    <message numerus="yes">
        <source>%n problem(s) stop the computation. Double-click one to go to its value; the results return once all are repaired.</source>
        <translation>
            <numerusform>%n problema impide el cálculo. Haga doble clic en él para ir a su valor; los resultados vuelven cuando esté reparado.</numerusform>
            <numerusform>%n problemas impiden el cálculo. Haga doble clic en uno para ir a su valor; los resultados vuelven cuando todos estén reparados.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProfileView</name>
    <message>
        <source>Drag to move this corner (snaps to %1 %3; Shift: %2 %3)</source>
        <translation>Arrastrar para mover esta esquina (ajusta a %1 %3; Mayús: %2 %3)</translation>
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
        <translation>No hay ninguna pieza abierta.

Abrir una pieza de ejemplo: Archivo &gt; Abrir ejemplo
Importar una pieza torneada de STEP o IGES: Archivo &gt; Importar STEP/IGES… (Ctrl+I)
Dibujar una pieza nueva: Archivo &gt; Nuevo (Ctrl+N) y editar sus elementos
Abrir un proyecto: Archivo &gt; Abrir… (Ctrl+O)</translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectAnalysis</name>
    <message numerus="yes">
        <source>Not computed: the project has %n problem(s), listed under Problems. Double-click one to go to its value.</source>
        <translation>
            <numerusform>Sin calcular: el proyecto tiene %n problema, listado en Problemas. Haga doble clic en él para ir a su valor.</numerusform>
            <numerusform>Sin calcular: el proyecto tiene %n problemas, listados en Problemas. Haga doble clic en uno para ir a su valor.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tolturn::ProjectDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
    <message>
        <source>Add tolerance %1</source>
        <translation>Añadir tolerancia %1</translation>
    </message>
    <message>
        <source>there is no tolerance %1</source>
        <translation>no existe la tolerancia %1</translation>
    </message>
    <message>
        <source>Edit tolerance %1</source>
        <translation>Editar tolerancia %1</translation>
    </message>
    <message>
        <source>Remove tolerance %1</source>
        <translation>Quitar tolerancia %1</translation>
    </message>
    <message>
        <source>Set datum %1 on %2</source>
        <translation>Definir referencia %1 en %2</translation>
    </message>
    <message>
        <source>Change planning settings</source>
        <translation>Cambiar la configuración de planificación</translation>
    </message>
    <message>
        <source>Change material to %1</source>
        <translation>Cambiar material a %1</translation>
    </message>
    <message>
        <source>Change machine to %1</source>
        <translation>Cambiar máquina a %1</translation>
    </message>
    <message>
        <source>Change tool</source>
        <translation>Cambiar herramienta</translation>
    </message>
    <message>
        <source>Change clamping</source>
        <translation>Cambiar sujeción</translation>
    </message>
    <message>
        <source>Change machine stiffness</source>
        <translation>Cambiar rigidez de la máquina</translation>
    </message>
    <message>
        <source>Change force model</source>
        <translation>Cambiar modelo de fuerzas</translation>
    </message>
    <message>
        <source>Change shop conditions</source>
        <translation>Cambiar condiciones del taller</translation>
    </message>
    <message>
        <source>Change boring bar</source>
        <translation>Cambiar barra de mandrinar</translation>
    </message>
    <message>
        <source>Change operations</source>
        <translation>Cambiar operaciones</translation>
    </message>
    <message>
        <source>the project has no operation %1 any more</source>
        <translation>el proyecto ya no tiene la operación %1</translation>
    </message>
</context>
<context>
    <name>tolturn::SettingsDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Preferencias</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Idioma del sistema</translation>
    </message>
    <message>
        <source>Millimetres (lengths in mm, deviations in µm)</source>
        <translation>Milímetros (longitudes en mm, desviaciones en µm)</translation>
    </message>
    <message>
        <source>Inches (lengths in in, deviations in µin)</source>
        <translation>Pulgadas (longitudes en in, desviaciones en µin)</translation>
    </message>
    <message>
        <source>Lengths on the drawing, in the feature and set-up panels and in the plots; deviations in the plots and the verdict table. Files, reports, cutting data and the ISO 286 tables stay in millimetres and micrometres.</source>
        <translation>Longitudes en el dibujo, en los paneles de elemento y de preparación y en los gráficos; desviaciones en los gráficos y en la tabla de veredictos. Los archivos, los informes, los datos de corte y las tablas ISO 286 siguen en milímetros y micrómetros.</translation>
    </message>
    <message>
        <source>A new language is used when TolTurn is next started.</source>
        <translation>Un nuevo idioma se usará la próxima vez que se inicie TolTurn.</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Idioma:</translation>
    </message>
    <message>
        <source>&amp;Units:</source>
        <translation>&amp;Unidades:</translation>
    </message>
    <message>
        <source>name in the report&apos;s title block</source>
        <translation>nombre en el cajetín del informe</translation>
    </message>
    <message>
        <source>&amp;Planner:</source>
        <translation>&amp;Planificador:</translation>
    </message>
    <message>
        <source>e.g. EUR, of the machine rate and tool costs</source>
        <translation>p. ej. EUR, de la tarifa de máquina y los costes de herramienta</translation>
    </message>
    <message>
        <source>&amp;Currency:</source>
        <translation>&amp;Moneda:</translation>
    </message>
    <message>
        <source>Measurement store</source>
        <translation>Almacén de mediciones</translation>
    </message>
    <message>
        <source>On this &amp;computer: %1</source>
        <translation>En este &amp;equipo: %1</translation>
    </message>
    <message>
        <source>&amp;Shop database (PostgreSQL), shared by every planner</source>
        <translation>Base de datos del &amp;taller (PostgreSQL), compartida por todos los planificadores</translation>
    </message>
    <message>
        <source>server name, or the folder of its socket (/var/run/postgresql)</source>
        <translation>nombre del servidor o la carpeta de su socket (/var/run/postgresql)</translation>
    </message>
    <message>
        <source>&amp;Test Connection</source>
        <translation>&amp;Probar conexión</translation>
    </message>
    <message>
        <source>TolTurn keeps no password: libpq reads it from ~/.pgpass, or the server needs none (peer authentication).</source>
        <translation>TolTurn no guarda ninguna contraseña: libpq la lee de ~/.pgpass, o el servidor no necesita ninguna (autenticación peer).</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Servidor:</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;uerto:</translation>
    </message>
    <message>
        <source>&amp;Database:</source>
        <translation>&amp;Base de datos:</translation>
    </message>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Usuario:</translation>
    </message>
    <message>
        <source>host</source>
        <translation>servidor</translation>
    </message>
    <message>
        <source>database</source>
        <translation>base de datos</translation>
    </message>
    <message>
        <source>user</source>
        <translation>usuario</translation>
    </message>
    <message>
        <source>The shop database needs its %1.</source>
        <translation>La base de datos del taller necesita su %1.</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Conectando con %1…</translation>
    </message>
    <message>
        <source>Connected to %1.</source>
        <translation>Conectado con %1.</translation>
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
        <translation>%1 (no está en la biblioteca de datos)</translation>
    </message>
    <message>
        <source>Length of the part in the jaws from its left end; the chuck face is at this z. The part is a beam built in there (Valiño et al. 2008, eq. 2–5).</source>
        <translation>Longitud de la pieza dentro de las garras desde su extremo izquierdo; la cara del plato está en esta z. La pieza es una viga empotrada en ese punto (Valiño et al. 2008, ec. 2–5).</translation>
    </message>
    <message>
        <source>Tool length out of the turret for the toolpost term (Valiño et al. 2008, eq. 6); &apos;from holder&apos; uses the holder&apos;s length.</source>
        <translation>Longitud de la herramienta fuera de la torreta para el término de la torreta (Valiño et al. 2008, ec. 6); &apos;según portaherramientas&apos; usa la longitud del portaherramientas.</translation>
    </message>
    <message>
        <source>from holder</source>
        <translation>según portaherramientas</translation>
    </message>
    <message>
        <source>Material and machine</source>
        <translation>Material y máquina</translation>
    </message>
    <message>
        <source>&amp;Material:</source>
        <translation>&amp;Material:</translation>
    </message>
    <message>
        <source>Mac&amp;hine:</source>
        <translation>Má&amp;quina:</translation>
    </message>
    <message>
        <source>Stiffness:</source>
        <translation>Rigidez:</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <source>ISO 1832 designation, e.g. CNMG 120408: shape, clearance, tolerance, type, size, thickness, corner radius.</source>
        <translation>Designación ISO 1832, p. ej. CNMG 120408: forma, ángulo de incidencia, tolerancia, tipo, tamaño, espesor, radio de punta.</translation>
    </message>
    <message>
        <source>&amp;Insert (ISO 1832):</source>
        <translation>&amp;Plaquita (ISO 1832):</translation>
    </message>
    <message>
        <source>H&amp;older (ISO 5608):</source>
        <translation>P&amp;ortaherramientas (ISO 5608):</translation>
    </message>
    <message>
        <source>&amp;Overhang:</source>
        <translation>&amp;Voladizo:</translation>
    </message>
    <message>
        <source>Clamping</source>
        <translation>Sujeción</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>Mé&amp;todo:</translation>
    </message>
    <message>
        <source>Clamped &amp;length:</source>
        <translation>&amp;Longitud de amarre:</translation>
    </message>
    <message>
        <source>Cutting conditions</source>
        <translation>Condiciones de corte</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Pasada</translation>
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
        <translation>Velocidad de corte vc: velocidad del husillo n = 1000 vc / (π D).</translation>
    </message>
    <message>
        <source>Feed f: chip thickness h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).</source>
        <translation>Avance f: espesor de viruta h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).</translation>
    </message>
    <message>
        <source>Depth of cut ap: chip width b = ap / sin κr (Kienzle).</source>
        <translation>Profundidad de corte ap: anchura de viruta b = ap / sin κr (Kienzle).</translation>
    </message>
    <message>
        <source>corner %1°, nose radius %2 mm</source>
        <translation>ángulo de punta %1°, radio de punta %2 mm</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>spindle k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad</source>
        <translation>husillo k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad</translation>
    </message>
    <message>
        <source>tailstock %1 N/mm</source>
        <translation>contrapunto %1 N/mm</translation>
    </message>
    <message>
        <source>centres %1 N/mm</source>
        <translation>puntos %1 N/mm</translation>
    </message>
    <message>
        <source>measured (%1): %2</source>
        <translation>medida (%1): %2</translation>
    </message>
    <message>
        <source>Change cutting conditions</source>
        <translation>Cambiar condiciones de corte</translation>
    </message>
    <message>
        <source>Machine stiffness not applied yet: %1.</source>
        <translation>Rigidez de la máquina aún no aplicada: %1.</translation>
    </message>
    <message>
        <source>Measured Test Bar</source>
        <translation>Barra de prueba medida</translation>
    </message>
    <message>
        <source>Measurements (*.csv *.txt);;All files (*)</source>
        <translation>Mediciones (*.csv *.txt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Enter Lc, the distance of the front spindle bearing behind the chuck face, before fitting the springs.</source>
        <translation>Introduzca Lc, la distancia del rodamiento delantero del husillo detrás de la cara del plato, antes de ajustar los muelles.</translation>
    </message>
    <message>
        <source>No springs fitted: %1</source>
        <translation>No se ajustaron muelles: %1</translation>
    </message>
    <message>
        <source>Test bar fit (Valiño et al. 2008 §III) of %1, %2: %3 points, RMS residual %4 µm, forces of the project&apos;s model</source>
        <translation>Ajuste de barra de prueba (Valiño et al. 2008 §III) de %1, %2: %3 puntos, residuo RMS %4 µm, fuerzas del modelo del proyecto</translation>
    </message>
    <message>
        <source>Springs fitted to %1 points (RMS %2 µm)%3; the bar&apos;s own bending was %4 % of the deviation at its far end.</source>
        <translation>Muelles ajustados a %1 puntos (RMS %2 µm)%3; la flexión propia de la barra fue el %4 % de la desviación en su extremo libre.</translation>
    </message>
    <message>
        <source>, radial and tangential</source>
        <translation>, radiales y tangenciales</translation>
    </message>
    <message>
        <source>, radial only</source>
        <translation>, solo radiales</translation>
    </message>
    <message>
        <source>not measured: the chuck is the published range of chuck stiffness, results at both ends; tailstock and centres are rigid for want of data (see the banner above the verdicts). Measure k1, k2, k3 (Valiño et al. 2008 §III) below or fit them to a test bar.</source>
        <translation>no medida: el plato es el rango publicado de rigidez de platos, resultados en ambos extremos; contrapunto y puntos son rígidos a falta de datos (vea el aviso sobre los veredictos). Mida k1, k2, k3 (Valiño et al. 2008 §III) abajo o ajústelos a una barra de prueba.</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Pieza</translation>
    </message>
    <message>
        <source>The number of the part drawing the tolerances come from (report title block)</source>
        <translation>El número del plano de la pieza del que proceden las tolerancias (cajetín del informe)</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Drawing no.:</source>
        <translation>N.º de &amp;plano:</translation>
    </message>
    <message>
        <source>&amp;Revision:</source>
        <translation>&amp;Revisión:</translation>
    </message>
    <message>
        <source>Diameter of the bar the part is turned from: the roughing passes remove the stock between it and the profile.</source>
        <translation>Diámetro de la barra de la que se tornea la pieza: las pasadas de desbaste quitan el material entre ella y el perfil.</translation>
    </message>
    <message>
        <source>&amp;Stock Ø:</source>
        <translation>Ø de &amp;bruto:</translation>
    </message>
    <message>
        <source>Change part name, drawing or stock</source>
        <translation>Cambiar nombre de la pieza, plano o bruto</translation>
    </message>
    <message>
        <source>roughing</source>
        <translation>desbaste</translation>
    </message>
    <message>
        <source>finishing</source>
        <translation>acabado</translation>
    </message>
    <message>
        <source>Boring bar</source>
        <translation>Barra de mandrinar</translation>
    </message>
    <message>
        <source>The bar that cuts the inner contour. Without one the bores are computed as if cut by the turning tool, without the bending of a bar.</source>
        <translation>La barra que mecaniza el contorno interior. Sin ella, los agujeros se calculan como si los mecanizara la herramienta de torneado, sin la flexión de una barra.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>%1 (Ø%2 mm, %3)</source>
        <translation>%1 (Ø%2 mm, %3)</translation>
    </message>
    <message>
        <source>material unknown</source>
        <translation>material desconocido</translation>
    </message>
    <message>
        <source>ISO 1832 designation of the boring bar&apos;s insert: its nose radius and the bar&apos;s entering angle give the forces in the bores.</source>
        <translation>Designación ISO 1832 de la plaquita de la barra de mandrinar: su radio de punta y el ángulo de posición de la barra dan las fuerzas en los agujeros.</translation>
    </message>
    <message>
        <source>bore depth</source>
        <translation>profundidad del agujero</translation>
    </message>
    <message>
        <source>The cutting edge&apos;s distance from the bar&apos;s axis, the maker&apos;s dimension f: the arm of the torque that twists the bar. &apos;bar radius&apos; takes the least it can be.</source>
        <translation>Distancia del filo al eje de la barra, la cota f del fabricante: el brazo del par que tuerce la barra. &apos;radio de la barra&apos; toma el mínimo posible.</translation>
    </message>
    <message>
        <source>bar radius</source>
        <translation>radio de la barra</translation>
    </message>
    <message>
        <source>&amp;Bar:</source>
        <translation>&amp;Barra:</translation>
    </message>
    <message>
        <source>Insert (ISO 1832):</source>
        <translation>Plaquita (ISO 1832):</translation>
    </message>
    <message>
        <source>Bar o&amp;verhang:</source>
        <translation>&amp;Voladizo de la barra:</translation>
    </message>
    <message>
        <source>Edge offset f:</source>
        <translation>Desplazamiento del filo f:</translation>
    </message>
    <message>
        <source>The part has bores: without a boring bar they are computed as if cut by the turning tool, without the bending of a bar.</source>
        <translation>La pieza tiene agujeros: sin barra de mandrinar se calculan como si los mecanizara la herramienta de torneado, sin la flexión de una barra.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a boring bar of the data library.</source>
        <translation>&quot;%1&quot; no es una barra de mandrinar de la biblioteca de datos.</translation>
    </message>
    <message>
        <source>L/D %1</source>
        <translation>L/D %1</translation>
    </message>
    <message>
        <source>L/D from the reach of the bore</source>
        <translation>L/D según el alcance del agujero</translation>
    </message>
    <message>
        <source>%1 bar, E = %2 GPa; %3; the maker allows up to %4 × D (%5).</source>
        <translation>Barra de %1, E = %2 GPa; %3; el fabricante permite hasta %4 × D (%5).</translation>
    </message>
    <message>
        <source>left end (as drawn)</source>
        <translation>extremo izquierdo (como en el plano)</translation>
    </message>
    <message>
        <source>right end (turned end for end)</source>
        <translation>extremo derecho (pieza invertida)</translation>
    </message>
    <message>
        <source>The end of the drawing the chuck holds (between centres: the driven end). Held at its right end, the part is computed and programmed turned end for end.</source>
        <translation>El extremo del plano que sujeta el plato (entre puntos: el extremo arrastrado). Sujetada por su extremo derecho, la pieza se calcula y se programa invertida.</translation>
    </message>
    <message>
        <source>Held &amp;end:</source>
        <translation>&amp;Extremo sujetado:</translation>
    </message>
    <message>
        <source>Boundary conditions of the workpiece beam: built in at the chuck face, supported by the tailstock centre, or by two centres (MODEL.md §3); a collet is built in at its face, its stiffness not published (taken as rigid, said in the verdicts).</source>
        <translation>Condiciones de contorno de la viga de la pieza: empotrada en la cara del plato, apoyada en el punto del contrapunto o entre dos puntos (MODEL.md §3); una pinza la empotra en su cara, sin rigidez publicada (tomada como rígida, indicado en los veredictos).</translation>
    </message>
    <message>
        <source>Diameter of the hole drilled (or cored) before the bar starts: the program roughs the bore from it. &apos;not given&apos; takes the bore as roughed to its finishing allowance before the program.</source>
        <translation>Diámetro del agujero taladrado (o de fundición) antes de que empiece la barra: el programa desbasta el agujero desde él. «no indicado» toma el agujero como desbastado a su creces de acabado antes del programa.</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>no indicado</translation>
    </message>
    <message>
        <source>Pilot &amp;hole Ø:</source>
        <translation>Agujero &amp;previo Ø:</translation>
    </message>
    <message>
        <source>Length of the bar out of its clamping to the cutting edge. &apos;bore depth&apos; takes the least that reaches the deepest bore from the right end face, with the turret 2 mm off it.</source>
        <translation>Longitud de la barra desde su sujeción hasta el filo. &apos;profundidad del agujero&apos; toma lo mínimo que alcanza el agujero más profundo desde la cara frontal derecha, con la torreta a 2 mm de ella.</translation>
    </message>
</context>
<context>
    <name>tolturn::SolidCheckDialog</name>
    <message>
        <source>The largest edge of the tetrahedra gmsh meshes the part with: smaller is more exact and slower</source>
        <translation>La arista más larga de los tetraedros con los que gmsh malla la pieza: más pequeña es más exacta y más lenta</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ejecutar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Check with Solid FE</source>
        <translation>Comprobar con sólido FE</translation>
    </message>
    <message>
        <source>%1: %2, %3 end held</source>
        <translation>%1: %2, extremo %3 sujetado</translation>
    </message>
    <message>
        <source>The part of the set-up is meshed in quadratic tetrahedra with gmsh, held as its clamping holds it, loaded by the cutting force at each station and solved with CalculiX; its deflection is compared with the beam&apos;s. A coarse mesh takes seconds, a fine one minutes. The project is not changed.</source>
        <translation>La pieza del montaje se malla en tetraedros cuadráticos con gmsh, sujetada como la sujeta su sujeción, cargada con la fuerza de corte en cada estación y resuelta con CalculiX; su flexión se compara con la de la viga. Una malla gruesa tarda segundos, una fina minutos. El proyecto no se modifica.</translation>
    </message>
    <message>
        <source>The set-up checked: its part as held and its finishing pass&apos;s force</source>
        <translation>El montaje comprobado: su pieza tal como está sujetada y la fuerza de su pasada de acabado</translation>
    </message>
    <message>
        <source>Tool positions, evenly along the supported length: one load case of CalculiX each</source>
        <translation>Posiciones de la herramienta, repartidas por igual a lo largo de la longitud apoyada: un caso de carga de CalculiX cada una</translation>
    </message>
    <message>
        <source>Operation:</source>
        <translation>Operación:</translation>
    </message>
    <message>
        <source>Stations:</source>
        <translation>Estaciones:</translation>
    </message>
    <message>
        <source>Mesh size:</source>
        <translation>Tamaño de malla:</translation>
    </message>
    <message>
        <source>default %1 %2: a fifth of the smallest outer diameter between the supports</source>
        <translation>por defecto %1 %2: una quinta parte del menor diámetro exterior entre los apoyos</translation>
    </message>
    <message>
        <source>Choose a mesh size of at least %1 %2: a finer mesh of a whole part takes gmsh and CalculiX hours and more memory than the computer has.</source>
        <translation>Elija un tamaño de malla de al menos %1 %2: una malla más fina de una pieza entera lleva a gmsh y CalculiX horas y más memoria de la que tiene el ordenador.</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Comprobando…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Cancelando…</translation>
    </message>
    <message>
        <source>done — %p%</source>
        <translation>terminado — %p%</translation>
    </message>
    <message>
        <source>The project cannot be checked:</source>
        <translation>El proyecto no se puede comprobar:</translation>
    </message>
    <message>
        <source>The check needs gmsh and CalculiX, and one of them is missing:</source>
        <translation>La comprobación necesita gmsh y CalculiX, y falta uno de ellos:</translation>
    </message>
    <message>
        <source>Meshing the part failed:</source>
        <translation>El mallado de la pieza ha fallado:</translation>
    </message>
    <message>
        <source>Solving failed:</source>
        <translation>La resolución ha fallado:</translation>
    </message>
    <message>
        <source>The check was cancelled; the project is unchanged.</source>
        <translation>La comprobación se ha cancelado; el proyecto no ha cambiado.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelada</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fallida</translation>
    </message>
    <message>
        <source>Checked in %1 s. The beam&apos;s radial deflection differs from the solid&apos;s by at most %2 % of the largest deflection.</source>
        <translation>Comprobado en %1 s. La deflexión radial de la viga difiere de la del sólido como máximo en un %2 % de la mayor deflexión.</translation>
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
        <translation>viga radial [%1]</translation>
    </message>
    <message>
        <source>solid radial [%1]</source>
        <translation>sólido radial [%1]</translation>
    </message>
    <message>
        <source>beam − solid [%]</source>
        <translation>viga − sólido [%]</translation>
    </message>
    <message>
        <source>beam tangential [%1]</source>
        <translation>viga tangencial [%1]</translation>
    </message>
    <message>
        <source>solid tangential [%1]</source>
        <translation>sólido tangencial [%1]</translation>
    </message>
    <message>
        <source>The tool position, from the end the set-up holds</source>
        <translation>La posición de la herramienta, desde el extremo que sujeta el montaje</translation>
    </message>
    <message>
        <source>(beam − solid) / solid of the radial deflection: positive where the beam is the softer</source>
        <translation>(viga − sólido) / sólido de la flexión radial: positivo donde la viga es la más flexible</translation>
    </message>
    <message>
        <source>Radial deflection of the part under the cutting force</source>
        <translation>Flexión radial de la pieza bajo la fuerza de corte</translation>
    </message>
    <message>
        <source>z from the held end [%1]</source>
        <translation>z desde el extremo sujetado [%1]</translation>
    </message>
    <message>
        <source>radial deflection [%1]</source>
        <translation>flexión radial [%1]</translation>
    </message>
    <message>
        <source>beam</source>
        <translation>viga</translation>
    </message>
    <message>
        <source>solid (CalculiX)</source>
        <translation>sólido (CalculiX)</translation>
    </message>
    <message>
        <source>Mesh: C3D10 tetrahedra of at most %1 %2, %3 nodes, %4 elements, %5 degrees of freedom · gmsh %6 s, CalculiX %7 s</source>
        <translation>Malla: tetraedros C3D10 de como mucho %1 %2, %3 nodos, %4 elementos, %5 grados de libertad · gmsh %6 s, CalculiX %7 s</translation>
    </message>
    <message>
        <source>Held: %1 · E = %2 MPa, ν = %3 · force at each station: Fc %4 N, Ff %5 N, Fp %6 N</source>
        <translation>Sujeción: %1 · E = %2 MPa, ν = %3 · fuerza en cada estación: Fc %4 N, Ff %5 N, Fp %6 N</translation>
    </message>
    <message>
        <source>Timoshenko radial [%1]</source>
        <translation>Timoshenko radial [%1]</translation>
    </message>
    <message>
        <source>The beam without its corrections for the root in the jaws and the shoulders (docs/solid-fe.md)</source>
        <translation>La viga sin sus correcciones del empotramiento en las garras y de los resaltes (docs/solid-fe.md)</translation>
    </message>
    <message>
        <source>beam without corrections</source>
        <translation>viga sin correcciones</translation>
    </message>
    <message>
        <source>beam (corrected)</source>
        <translation>viga (corregida)</translation>
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
        <translation>Rigidez medida de la máquina</translation>
    </message>
    <message>
        <source>Spindle–chuck springs (Valiño et al. 2008, §III, eq. 2–4): k1 radial translation [N/mm], k2 and k3 rotation [N·mm/rad] about the pivot Lc behind the chuck face.</source>
        <translation>Muelles husillo–plato (Valiño et al. 2008, §III, ec. 2–4): k1 traslación radial [N/mm], k2 y k3 giro [N·mm/rad] alrededor del pivote Lc detrás de la cara del plato.</translation>
    </message>
    <message>
        <source>Support stiffness of the centre at the part&apos;s right (or both) ends [N/mm], as a spring under the workpiece beam (MODEL.md §3).</source>
        <translation>Rigidez de apoyo del punto en el extremo derecho de la pieza (o en ambos extremos) [N/mm], como un muelle bajo la viga de la pieza (MODEL.md §3).</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Lc: distance of the k2 spring behind the chuck face (Valiño et al. 2008, Fig. 2).</source>
        <translation>Lc: distancia del muelle k2 detrás de la cara del plato (Valiño et al. 2008, Fig. 2).</translation>
    </message>
    <message>
        <source>who measured it, when, how</source>
        <translation>quién la midió, cuándo y cómo</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>Fuente:</translation>
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
        <translation>tangencial [N/mm]</translation>
    </message>
    <message>
        <source>Spindle radial</source>
        <translation>Husillo radial</translation>
    </message>
    <message>
        <source>Spindle tangential</source>
        <translation>Husillo tangencial</translation>
    </message>
    <message>
        <source>Tailstock</source>
        <translation>Contrapunto</translation>
    </message>
    <message>
        <source>Centres</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <source> Radial.</source>
        <translation> Radial.</translation>
    </message>
    <message>
        <source> Tangential.</source>
        <translation> Tangencial.</translation>
    </message>
    <message>
        <source>spindle radial k1, k2, k3</source>
        <translation>husillo radial k1, k2, k3</translation>
    </message>
    <message>
        <source>spindle tangential k1, k2, k3</source>
        <translation>husillo tangencial k1, k2, k3</translation>
    </message>
    <message>
        <source>tailstock radial and tangential</source>
        <translation>contrapunto radial y tangencial</translation>
    </message>
    <message>
        <source>centres radial and tangential</source>
        <translation>puntos radial y tangencial</translation>
    </message>
    <message>
        <source>enter all of %1</source>
        <translation>introduzca todos los valores de %1</translation>
    </message>
    <message>
        <source>enter the pivot distance Lc of the spindle springs</source>
        <translation>introduzca la distancia de pivote Lc de los muelles del husillo</translation>
    </message>
    <message>
        <source>enter where the numbers come from (source)</source>
        <translation>indique la procedencia de los valores (fuente)</translation>
    </message>
    <message>
        <source>Fit from Test Bar…</source>
        <translation>Ajustar con barra de prueba…</translation>
    </message>
    <message>
        <source>Valiño et al. 2008 §III: the open project is a stiff bar turned in the chuck; a CSV of its measured deviation (z_mm, radial_um, optionally tangential_um) gives k1, k2, k3 for the Lc entered above.</source>
        <translation>Valiño et al. 2008 §III: el proyecto abierto es una barra rígida torneada en el plato; un CSV de su desviación medida (z_mm, radial_um, opcionalmente tangential_um) da k1, k2, k3 para el Lc introducido arriba.</translation>
    </message>
</context>
<context>
    <name>tolturn::ToleranceDialog</name>
    <message>
        <source>ISO 286 class</source>
        <translation>Clase ISO 286</translation>
    </message>
    <message>
        <source>Limit deviations</source>
        <translation>Diferencias límite</translation>
    </message>
    <message>
        <source>Add Tolerance</source>
        <translation>Añadir tolerancia</translation>
    </message>
    <message>
        <source>Edit Tolerance %1</source>
        <translation>Editar tolerancia %1</translation>
    </message>
    <message>
        <source>To face</source>
        <translation>Hasta la cara</translation>
    </message>
    <message>
        <source>Upper deviation</source>
        <translation>Diferencia superior</translation>
    </message>
    <message>
        <source>Lower deviation</source>
        <translation>Diferencia inferior</translation>
    </message>
    <message>
        <source>e.g. h6, H7, js12</source>
        <translation>p. ej. h6, H7, js12</translation>
    </message>
    <message>
        <source>ISO 286-1 tolerance class: small letters for shafts, capitals for holes.</source>
        <translation>Clase de tolerancia ISO 286-1: minúsculas para ejes, mayúsculas para agujeros.</translation>
    </message>
    <message>
        <source>Tolerance zone t</source>
        <translation>Zona de tolerancia t</translation>
    </message>
    <message>
        <source>Datums</source>
        <translation>Referencias</translation>
    </message>
    <message>
        <source>no datum defined yet</source>
        <translation>aún no hay ninguna referencia definida</translation>
    </message>
    <message>
        <source>e.g. A; defined: %1</source>
        <translation>p. ej. A; definidas: %1</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Característica</translation>
    </message>
    <message>
        <source>at %1 mm: upper %2 µm, lower %3 µm (%4 = %5 µm)</source>
        <translation>para %1 mm: superior %2 µm, inferior %3 µm (%4 = %5 µm)</translation>
    </message>
</context>
<context>
    <name>tolturn::TolerancePanel</name>
    <message>
        <source>Add…</source>
        <translation>Añadir…</translation>
    </message>
    <message>
        <source>Edit…</source>
        <translation>Editar…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Set Datum…</source>
        <translation>Definir referencia…</translation>
    </message>
    <message>
        <source>Add a tolerance on the feature selected in the drawing</source>
        <translation>Añadir una tolerancia al elemento seleccionado en el dibujo</translation>
    </message>
    <message>
        <source>Make the feature selected in the drawing a datum (ISO 5459)</source>
        <translation>Convertir el elemento seleccionado en el dibujo en una referencia (ISO 5459)</translation>
    </message>
    <message>
        <source>Set Datum</source>
        <translation>Definir referencia</translation>
    </message>
    <message>
        <source>Datum letter for feature %1 (ISO 5459):</source>
        <translation>Letra de referencia para el elemento %1 (ISO 5459):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Machine:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Máquina:&lt;/b&gt; %1</translation>
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
        <translation>Característica</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Especificación</translation>
    </message>
    <message>
        <source>Utilisation</source>
        <translation>Utilización</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <source>Predicted [%1]</source>
        <translation>Previsto [%1]</translation>
    </message>
    <message>
        <source>Limit [%1]</source>
        <translation>Límite [%1]</translation>
    </message>
    <message>
        <source>chuck %1</source>
        <translation>plato %1</translation>
    </message>
    <message>
        <source>tailstock %1</source>
        <translation>contrapunto %1</translation>
    </message>
    <message>
        <source>The smallest radial stiffness of the chuck (at its face) and of the tailstock (or of both centres) with which this tolerance passes as programmed at the planned conditions, the other supports as assumed.</source>
        <translation>La menor rigidez radial del plato (en su cara) y del contrapunto (o de ambos puntos) con la que esta tolerancia cumple tal como está programada en las condiciones planificadas, con los demás apoyos según lo supuesto.</translation>
    </message>
    <message>
        <source>On the machine range</source>
        <translation>En el rango de máquinas</translation>
    </message>
    <message>
        <source>Stiffness needed</source>
        <translation>Rigidez necesaria</translation>
    </message>
    <message>
        <source>%1 is cut in %2: choose that set-up to see its verdict</source>
        <translation>%1 se mecaniza en %2: elija ese montaje para ver su veredicto</translation>
    </message>
    <message>
        <source>collet %1</source>
        <translation>pinza %1</translation>
    </message>
</context>
</TS>

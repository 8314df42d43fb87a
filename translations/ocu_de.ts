<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>CommandLine</name>
    <message>
        <source>Mixed-fleet Operator Control Unit: JAUS ground vehicles, ISO 23725 autonomous haulage and OSYRIS rollers and pavers on one console.
Without --config it starts on the built-in simulated site.</source>
        <translation>Operator Control Unit für gemischte Flotten: JAUS-Bodenfahrzeuge, autonome Förderung nach ISO 23725 sowie OSYRIS-Walzen und -Fertiger auf einer Konsole.
Ohne --config startet sie mit der eingebauten simulierten Baustelle.</translation>
    </message>
    <message>
        <source>Site configuration (JSON, see docs/site-config.md). Default: the built-in simulated site.</source>
        <translation>Baustellenkonfiguration (JSON, siehe docs/site-config.md). Standard: die eingebaute simulierte Baustelle.</translation>
    </message>
    <message>
        <source>Do not start the built-in simulators, even if the configuration enables them.</source>
        <translation>Eingebaute Simulatoren nicht starten, auch wenn die Konfiguration sie aktiviert.</translation>
    </message>
    <message>
        <source>Write a PNG screenshot to FILE after --settle seconds, then exit 0.</source>
        <translation>Nach --settle Sekunden ein PNG-Bildschirmfoto nach FILE schreiben, dann mit 0 beenden.</translation>
    </message>
    <message>
        <source>What --screenshot captures: all (the whole window) or one panel: %1.</source>
        <translation>Was --screenshot aufnimmt: all (das ganze Fenster) oder ein Panel: %1.</translation>
    </message>
    <message>
        <source>Window size for the screenshot, e.g. 1600x1000.</source>
        <translation>Fenstergröße für das Bildschirmfoto, z. B. 1600x1000.</translation>
    </message>
    <message>
        <source>Seconds to let live data arrive before the screenshot (default 3).</source>
        <translation>Sekunden Wartezeit auf Live-Daten vor dem Bildschirmfoto (Standard 3).</translation>
    </message>
    <message>
        <source>User interface language: en, de or fr (default: the system locale).</source>
        <translation>Sprache der Oberfläche: en, de oder fr (Standard: Systemgebietsschema).</translation>
    </message>
    <message>
        <source>Enable debug output for these logging categories, comma-separated: ocu.jaus, ocu.iso, ocu.osyris, ocu.ui, ocu.sim, ocu.* (Qt wildcard rules).</source>
        <translation>Debug-Ausgabe für diese Logging-Kategorien aktivieren, durch Kommas getrennt: ocu.jaus, ocu.iso, ocu.osyris, ocu.ui, ocu.sim, ocu.* (Qt-Platzhalterregeln).</translation>
    </message>
    <message>
        <source>No window: print one JSON line per machine change and per event on stdout, read JSON-line commands on stdin (see README).</source>
        <translation>Kein Fenster: je Maschinenänderung und je Ereignis eine JSON-Zeile auf stdout ausgeben, JSON-Zeilen-Befehle von stdin lesen (siehe README).</translation>
    </message>
    <message>
        <source>With --headless: stop after SECONDS (default: run until stdin closes).</source>
        <translation>Mit --headless: nach SECONDS beenden (Standard: bis stdin geschlossen wird).</translation>
    </message>
    <message>
        <source>Start with the default panel layout instead of the saved one.</source>
        <translation>Mit dem Standard-Panel-Layout statt dem gespeicherten starten.</translation>
    </message>
    <message>
        <source>Unexpected argument: %1</source>
        <translation>Unerwartetes Argument: %1</translation>
    </message>
    <message>
        <source>--view: unknown view &quot;%1&quot;; use all, %2</source>
        <translation>--view: unbekannte Ansicht „%1“; zulässig: all, %2</translation>
    </message>
    <message>
        <source>--size: expected WxH such as 1600x1000, got &quot;%1&quot;</source>
        <translation>--size: WxH erwartet, z. B. 1600x1000, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--size: %1 is outside 320x240 .. 8192x8192</source>
        <translation>--size: %1 liegt außerhalb von 320x240 .. 8192x8192</translation>
    </message>
    <message>
        <source>--settle: expected seconds between 0 and 3600, got &quot;%1&quot;</source>
        <translation>--settle: Sekunden zwischen 0 und 3600 erwartet, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--lang: &quot;%1&quot; is not one of en, de, fr</source>
        <translation>--lang: „%1“ ist nicht en, de oder fr</translation>
    </message>
    <message>
        <source>--duration: expected seconds &gt;= 0, got &quot;%1&quot;</source>
        <translation>--duration: Sekunden &gt;= 0 erwartet, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--headless and --screenshot cannot be combined</source>
        <translation>--headless und --screenshot können nicht kombiniert werden</translation>
    </message>
    <message>
        <source>Check the site configuration FILE, print each problem as file:line, start nothing; exit 0 when valid, 1 when not.</source>
        <translation>Die Baustellenkonfiguration FILE prüfen, jedes Problem als Datei:Zeile ausgeben, nichts starten; Exit-Code 0 wenn gültig, sonst 1.</translation>
    </message>
    <message>
        <source>all:PANEL: the whole window with that panel in front.</source>
        <translation>all:PANEL: das ganze Fenster mit diesem Feld im Vordergrund.</translation>
    </message>
    <message>
        <source>With --headless: also take JSON-line commands on a local socket at PATH (mode 0660: owner and group); the run then ends on SIGTERM or --duration, not at the end of stdin.</source>
        <translation>Mit --headless: zusätzlich JSON-Zeilen-Befehle über einen lokalen Socket unter PATH annehmen (Modus 0660: Eigentümer und Gruppe); der Lauf endet dann mit SIGTERM oder --duration, nicht am Ende von stdin.</translation>
    </message>
    <message>
        <source>With --headless: write the shift report as PDF to FILE when the run ends.</source>
        <translation>Mit --headless: den Schichtbericht bei Laufende als PDF nach FILE schreiben.</translation>
    </message>
    <message>
        <source>With --headless: write the shift report as CSV to FILE when the run ends.</source>
        <translation>Mit --headless: den Schichtbericht bei Laufende als CSV nach FILE schreiben.</translation>
    </message>
    <message>
        <source>Start with the night palette.</source>
        <translation>Mit der Nachtpalette starten.</translation>
    </message>
    <message>
        <source>--workspace: &quot;%1&quot; is not one of dispatch, compaction, ugv, monitor, all</source>
        <translation>--workspace: „%1“ ist nicht dispatch, compaction, ugv, monitor oder all</translation>
    </message>
    <message>
        <source>--command-socket needs --headless</source>
        <translation>--command-socket erfordert --headless</translation>
    </message>
    <message>
        <source>--shift-report/--shift-csv need --headless (in the window: Production panel, Shift report)</source>
        <translation>--shift-report/--shift-csv erfordern --headless (im Fenster: Feld Produktion, Schichtbericht)</translation>
    </message>
</context>
<context>
    <name>CommandResult</name>
    <message>
        <source>no target: nothing sent</source>
        <translation>kein Ziel: nichts gesendet</translation>
    </message>
    <message>
        <source>sent to %1</source>
        <translation>gesendet an %1</translation>
    </message>
    <message>
        <source>NOT sent: %1</source>
        <translation>NICHT gesendet: %1</translation>
    </message>
    <message>
        <source>sent to %1; NOT sent: %2</source>
        <translation>gesendet an %1; NICHT gesendet: %2</translation>
    </message>
</context>
<context>
    <name>ConsoleApp</name>
    <message>
        <source>The site configuration was refused:
%1</source>
        <translation>Die Baustellenkonfiguration wurde abgelehnt:
%1</translation>
    </message>
    <message>
        <source>Operator Control Unit</source>
        <translation>Bedienstation</translation>
    </message>
    <message>
        <source>Operator Control Unit — %1</source>
        <translation>Bedienstation — %1</translation>
    </message>
    <message>
        <source>%1: the site configuration is valid (%2)</source>
        <translation>%1: die Baustellenkonfiguration ist gültig (%2)</translation>
    </message>
</context>
<context>
    <name>HeadlessSocket</name>
    <message>
        <source>%1: another console answers on this command socket</source>
        <translation>%1: an diesem Befehls-Socket antwortet bereits eine andere Konsole</translation>
    </message>
    <message>
        <source>%1: cannot open the command socket: %2</source>
        <translation>%1: Befehls-Socket kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1: cannot set the command socket&apos;s mode</source>
        <translation>%1: der Modus des Befehls-Sockets kann nicht gesetzt werden</translation>
    </message>
</context>
<context>
    <name>JausModule</name>
    <message>
        <source>mission_upload: %1; nothing sent</source>
        <translation>mission_upload: %1; nichts gesendet</translation>
    </message>
    <message>
        <source>Replay: the missions as the vehicles reported them then; commands are disabled.</source>
        <translation>Wiedergabe: die Missionen, wie die Fahrzeuge sie damals meldeten; Befehle sind gesperrt.</translation>
    </message>
    <message>
        <source>Recorded mission</source>
        <translation>Aufgezeichnete Mission</translation>
    </message>
</context>
<context>
    <name>MissionReplayBridge</name>
    <message>
        <source>replay: commands are disabled</source>
        <translation>Wiedergabe: Befehle sind gesperrt</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Compaction design not loaded: %1</source>
        <translation>Verdichtungsentwurf nicht geladen: %1</translation>
    </message>
    <message>
        <source>Queue</source>
        <translation>Warten</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Ansetzen</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Laden</translation>
    </message>
    <message>
        <source>Haul</source>
        <translation>Transport</translation>
    </message>
    <message>
        <source>Dump</source>
        <translation>Kippen</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>Rückfahrt</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>Sonstiges</translation>
    </message>
    <message>
        <source>Tonnes over the shift: %1 t in %2 loads</source>
        <translation>Tonnen über die Schicht: %1 t in %2 Ladungen</translation>
    </message>
    <message>
        <source>Dumped (t)</source>
        <translation>Gekippt (t)</translation>
    </message>
    <message>
        <source>Plan (t, %1 t/shift)</source>
        <translation>Plan (t, %1 t/Schicht)</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>Cycle time breakdown (average minutes per cycle)</source>
        <translation>Aufteilung der Umlaufzeit (Minuten je Umlauf, Mittelwert)</translation>
    </message>
    <message>
        <source>Shift</source>
        <translation>Schicht</translation>
    </message>
    <message>
        <source>Shift report</source>
        <translation>Schichtbericht</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Shift report — %1</source>
        <translation>Schichtbericht — %1</translation>
    </message>
    <message>
        <source>Shift %1 to %2 · written %3</source>
        <translation>Schicht %1 bis %2 · geschrieben %3</translation>
    </message>
    <message>
        <source>plan %1 t for the shift, %2 t due by now (%3 %)</source>
        <translation>Plan %1 t für die Schicht, %2 t bis jetzt fällig (%3 %)</translation>
    </message>
    <message>
        <source>no plan set</source>
        <translation>kein Plan gesetzt</translation>
    </message>
    <message>
        <source>%1 loads, %2 t dumped, %3 cycles, average cycle %4 · %5</source>
        <translation>%1 Ladungen, %2 t gekippt, %3 Umläufe, mittlerer Umlauf %4 · %5</translation>
    </message>
    <message>
        <source>%1 loads were dumped without a reported weight (not in the tonnes)</source>
        <translation>%1 Ladungen wurden ohne gemeldetes Gewicht gekippt (nicht in den Tonnen)</translation>
    </message>
    <message>
        <source>(no site map available for the snapshot)</source>
        <translation>(keine Lagekarte für die Momentaufnahme verfügbar)</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>Ladungen</translation>
    </message>
    <message>
        <source>Tonnes</source>
        <translation>Tonnen</translation>
    </message>
    <message>
        <source>t/load</source>
        <translation>t/Ladung</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Umläufe</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Umlauf</translation>
    </message>
    <message>
        <source>Trucks (cycle parts: average min:s per cycle)</source>
        <translation>Lkw (Umlaufteile: Mittelwert min:s je Umlauf)</translation>
    </message>
    <message>
        <source>Shovels (load areas)</source>
        <translation>Bagger (Ladestellen)</translation>
    </message>
    <message>
        <source>Dumps and crusher</source>
        <translation>Kippen und Brecher</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
</context>
<context>
    <name>Recording</name>
    <message>
        <source>%1: no such file</source>
        <translation>%1: Datei existiert nicht</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1 is not an OCU recording (%2)</source>
        <translation>%1 ist keine OCU-Aufzeichnung (%2)</translation>
    </message>
    <message>
        <source>%1 is not an OCU recording</source>
        <translation>%1 ist keine OCU-Aufzeichnung</translation>
    </message>
    <message>
        <source>%1: recording schema %2 is not supported</source>
        <translation>%1: Aufzeichnungsschema %2 wird nicht unterstützt</translation>
    </message>
    <message>
        <source> - not every target reached</source>
        <translation> - nicht jedes Ziel erreicht</translation>
    </message>
    <message>
        <source>the output is not writable</source>
        <translation>die Ausgabe ist nicht beschreibbar</translation>
    </message>
    <message>
        <source>write failed: %1</source>
        <translation>Schreiben fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>%1 exists already</source>
        <translation>%1 existiert bereits</translation>
    </message>
    <message>
        <source>the window ends before it starts</source>
        <translation>das Zeitfenster endet, bevor es beginnt</translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>%1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>slice to %1 failed: %2</source>
        <translation>Ausschnitt nach %1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>Replay</name>
    <message>
        <source>Replay: acknowledgements are replayed, not made</source>
        <translation>Wiedergabe: Quittierungen werden wiedergegeben, nicht erteilt</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>REPLAY — %1 — recorded %2 to %3 UTC — not live, commands disabled</source>
        <translation>WIEDERGABE — %1 — aufgezeichnet %2 bis %3 UTC — nicht live, Befehle deaktiviert</translation>
    </message>
    <message>
        <source>Replay: commands are disabled</source>
        <translation>Wiedergabe: Befehle sind deaktiviert</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>This recording holds no pass counts.</source>
        <translation>Diese Aufzeichnung enthält keine Überfahrtszahlen.</translation>
    </message>
    <message>
        <source>Replay: commands are disabled. This panel acts on live machines only.</source>
        <translation>Wiedergabe: Befehle sind deaktiviert. Dieses Feld wirkt nur auf Maschinen im Live-Betrieb.</translation>
    </message>
    <message>
        <source>--from/--to: not a time</source>
        <translation>--from/--to: keine Zeitangabe</translation>
    </message>
    <message>
        <source>--at: &quot;%1&quot; is not a time</source>
        <translation>--at: „%1“ ist keine Zeitangabe</translation>
    </message>
    <message>
        <source>Operator Control Unit — REPLAY %1</source>
        <translation>Bedienstation — WIEDERGABE %1</translation>
    </message>
</context>
<context>
    <name>Screenshot</name>
    <message>
        <source>unknown view &quot;%1&quot;</source>
        <translation>unbekannte Ansicht „%1“</translation>
    </message>
    <message>
        <source>nothing to grab for view &quot;%1&quot;</source>
        <translation>nichts aufzunehmen für Ansicht „%1“</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>SiteLoader</name>
    <message>
        <source>%1: cannot open the site configuration: %2</source>
        <translation>%1: Baustellenkonfiguration kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1: larger than 64 MiB</source>
        <translation>%1: größer als 64 MiB</translation>
    </message>
</context>
<context>
    <name>ocu</name>
    <message>
        <source>Folder for this run&apos;s flight recording (default: record.dir of the site configuration, else the user&apos;s data folder).</source>
        <translation>Ordner für die Flugschreiber-Aufzeichnung dieses Laufs (Standard: record.dir der Baustellenkonfiguration, sonst der Datenordner des Benutzers).</translation>
    </message>
    <message>
        <source>Do not record this run.</source>
        <translation>Diesen Lauf nicht aufzeichnen.</translation>
    </message>
    <message>
        <source>Replay a flight recording (no protocol stacks, commands disabled).</source>
        <translation>Eine Flugschreiber-Aufzeichnung wiedergeben (keine Protokollstacks, Befehle deaktiviert).</translation>
    </message>
    <message>
        <source>With --replay: start at T (seconds after the start, HH:MM:SS UTC or ISO 8601).</source>
        <translation>Mit --replay: bei T beginnen (Sekunden nach dem Start, HH:MM:SS UTC oder ISO 8601).</translation>
    </message>
    <message>
        <source>With --replay: playing speed 0.1 to 16 (--headless: default as fast as possible).</source>
        <translation>Mit --replay: Wiedergabegeschwindigkeit 0,1 bis 16 (--headless: standardmäßig so schnell wie möglich).</translation>
    </message>
    <message>
        <source>With --replay: write the window --from/--to as JSON lines and exit.</source>
        <translation>Mit --replay: das Fenster --from/--to als JSON-Zeilen schreiben und beenden.</translation>
    </message>
    <message>
        <source>With --replay: write machine states of the window as CSV and exit.</source>
        <translation>Mit --replay: Maschinenzustände des Fensters als CSV schreiben und beenden.</translation>
    </message>
    <message>
        <source>With --replay: write the window as a new recording and exit.</source>
        <translation>Mit --replay: das Fenster als neue Aufzeichnung schreiben und beenden.</translation>
    </message>
    <message>
        <source>Start of the export window (as --at).</source>
        <translation>Beginn des Exportfensters (wie --at).</translation>
    </message>
    <message>
        <source>End of the export window (as --at).</source>
        <translation>Ende des Exportfensters (wie --at).</translation>
    </message>
    <message>
        <source>Start in this workspace: dispatch, compaction, ugv, monitor or all (default: the one last used, else the operator&apos;s role&apos;s).</source>
        <translation>In diesem Arbeitsbereich starten: dispatch, compaction, ugv, monitor oder all (Standard: der zuletzt benutzte, sonst der zur Rolle des Bedieners passende).</translation>
    </message>
    <message>
        <source>--speed: expected 0.1 to 16, got &quot;%1&quot;</source>
        <translation>--speed: 0,1 bis 16 erwartet, erhalten: „%1“</translation>
    </message>
    <message>
        <source>--at, --speed, --export-* and --from/--to need --replay FILE</source>
        <translation>--at, --speed, --export-* und --from/--to erfordern --replay FILE</translation>
    </message>
</context>
<context>
    <name>ocu::AlarmModel</name>
    <message>
        <source>link %1 lost%2</source>
        <translation>Verbindung %1 verloren%2</translation>
    </message>
    <message>
        <source>link %1 restored</source>
        <translation>Verbindung %1 wiederhergestellt</translation>
    </message>
    <message>
        <source>no data from %1</source>
        <translation>keine Daten von %1</translation>
    </message>
    <message>
        <source>health fault</source>
        <translation>Zustandsfehler</translation>
    </message>
    <message>
        <source>Time (UTC)</source>
        <translation>Zeit (UTC)</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Ack</source>
        <translation>Quitt.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>NO</source>
        <translation>NEIN</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Priorität</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>shelved until %1</source>
        <translation>zurückgestellt bis %1</translation>
    </message>
    <message>
        <source>
… and %1 more</source>
        <translation>
… und %1 weitere</translation>
    </message>
</context>
<context>
    <name>ocu::AutoDispatcher</name>
    <message>
        <source>way %1</source>
        <translation>Weg %1</translation>
    </message>
    <message>
        <source>Auto dispatch ON (%1): idle FMS trucks go to the shortest queue</source>
        <translation>Automatische Disposition EIN (%1): freie FMS-Lkw fahren zur kürzesten Warteschlange</translation>
    </message>
    <message>
        <source>Auto dispatch OFF (%1)</source>
        <translation>Automatische Disposition AUS (%1)</translation>
    </message>
    <message>
        <source>Auto dispatch: %1</source>
        <translation>Automatische Disposition: %1</translation>
    </message>
    <message>
        <source>%1 rejected way %2: %3</source>
        <translation>%1 hat Weg %2 abgelehnt: %3</translation>
    </message>
    <message>
        <source>%1 did not report the assignment to way %2 within %3 s</source>
        <translation>%1 hat den Auftrag zu Weg %2 nicht binnen %3 s gemeldet</translation>
    </message>
    <message>
        <source>%1: %2 at %3 (queue %4)</source>
        <translation>%1: %2 bei %3 (Warteschlange %4)</translation>
    </message>
    <message>
        <source>%1 — sent</source>
        <translation>%1 — gesendet</translation>
    </message>
    <message>
        <source>%1 — NOT sent: %2</source>
        <translation>%1 — NICHT gesendet: %2</translation>
    </message>
</context>
<context>
    <name>ocu::AxisDisplay</name>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>turn</source>
        <translation>drehen</translation>
    </message>
    <message>
        <source>axis %1</source>
        <translation>Achse %1</translation>
    </message>
</context>
<context>
    <name>ocu::CommandGate</name>
    <message>
        <source>protocol stack</source>
        <translation>Protokollstack</translation>
    </message>
    <message>
        <source>stack did not answer within %1 ms</source>
        <translation>Stack hat nicht binnen %1 ms geantwortet</translation>
    </message>
    <message>
        <source>no protocol bridge registered: nothing sent</source>
        <translation>keine Protokollbrücke registriert: nichts gesendet</translation>
    </message>
    <message>
        <source>unknown machine %1</source>
        <translation>unbekannte Maschine %1</translation>
    </message>
    <message>
        <source>the console is locked: only stops are accepted</source>
        <translation>die Konsole ist gesperrt: nur Stopps werden angenommen</translation>
    </message>
    <message>
        <source>release needs a deliberate confirmation</source>
        <translation>Freigeben erfordert eine bewusste Bestätigung</translation>
    </message>
    <message>
        <source>no %1 bridge in this console: nothing sent</source>
        <translation>keine %1-Brücke in dieser Konsole: nichts gesendet</translation>
    </message>
    <message>
        <source>%1 already reports being stopped</source>
        <translation>%1 meldet bereits, gestoppt zu sein</translation>
    </message>
    <message>
        <source>%1 has not reported being stopped %2 ms after the stop command was sent</source>
        <translation>%1 hat %2 ms nach dem Stoppbefehl noch keinen Stopp gemeldet</translation>
    </message>
    <message>
        <source>%1: OSYRIS carries no stop state, so no machine can confirm the stop; the STOP text went to the drivers&apos; displays</source>
        <translation>%1: OSYRIS hat keinen Stoppzustand, daher kann keine Maschine den Stopp bestätigen; der STOP-Text ging an die Fahrerdisplays</translation>
    </message>
    <message>
        <source>%1 %2 ms after the command</source>
        <translation>%1 %2 ms nach dem Befehl</translation>
    </message>
    <message>
        <source>%1 already reports the effect of %2</source>
        <translation>%1 meldet bereits die Wirkung von %2</translation>
    </message>
    <message>
        <source>%1 has not confirmed %2 %3 ms after the command was sent</source>
        <translation>%1 hat %2 %3 ms nach dem Senden des Befehls nicht bestätigt</translation>
    </message>
</context>
<context>
    <name>ocu::CommandPermissionHint</name>
    <message>
        <source>Not permitted</source>
        <translation>Nicht erlaubt</translation>
    </message>
</context>
<context>
    <name>ocu::CommandPermissions</name>
    <message>
        <source>monitor</source>
        <translation>Beobachter</translation>
    </message>
    <message>
        <source>dispatcher</source>
        <translation>Disponent</translation>
    </message>
    <message>
        <source>site manager</source>
        <translation>Baustellenleiter</translation>
    </message>
    <message>
        <source>UGV operator</source>
        <translation>UGV-Bediener</translation>
    </message>
    <message>
        <source>supervisor</source>
        <translation>Schichtleiter</translation>
    </message>
    <message>
        <source>admin</source>
        <translation>Administrator</translation>
    </message>
    <message>
        <source>%1 is not permitted to any role at this console</source>
        <translation>%1 ist an dieser Konsole keiner Rolle erlaubt</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 oder %2</translation>
    </message>
    <message>
        <source>%1 needs the %2 role (you are %3)</source>
        <translation>%1 erfordert die Rolle %2 (Sie sind %3)</translation>
    </message>
    <message>
        <source>Not permitted to any role at this console</source>
        <translation>An dieser Konsole keiner Rolle erlaubt</translation>
    </message>
    <message>
        <source>Needs the %1 role (you are %2)</source>
        <translation>Erfordert die Rolle %1 (Sie sind %2)</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionMapOverlay</name>
    <message>
        <source>New area: %1 points (3 needed)</source>
        <translation>Neue Fläche: %1 Punkte (3 nötig)</translation>
    </message>
    <message>
        <source>New area: %1 points, %2 m²</source>
        <translation>Neue Fläche: %1 Punkte, %2 m²</translation>
    </message>
    <message>
        <source>click adds a point · Enter, double click or the first point closes · Backspace undoes · Esc cancels</source>
        <translation>Klick setzt einen Punkt · Enter, Doppelklick oder der erste Punkt schließt · Rücktaste nimmt zurück · Esc bricht ab</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionPanel</name>
    <message>
        <source>Lift:</source>
        <translation>Lage:</translation>
    </message>
    <message>
        <source>Top view</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Covered %</source>
        <translation>Überfahren %</translation>
    </message>
    <message>
        <source>Target %</source>
        <translation>Im Ziel %</translation>
    </message>
    <message>
        <source>Covered cells within the target passes, % of the area</source>
        <translation>Überfahrene Zellen mit Übergängen im Zielbereich, % der Fläche</translation>
    </message>
    <message>
        <source>Under %</source>
        <translation>Unter Ziel %</translation>
    </message>
    <message>
        <source>Over %</source>
        <translation>Über Ziel %</translation>
    </message>
    <message>
        <source>Incompl.</source>
        <translation>Unvollst.</translation>
    </message>
    <message>
        <source>Cells a given-up ribbon gap may have passed over: their counts are lower bounds</source>
        <translation>Zellen, über die eine aufgegebene Lücke im Band gegangen sein kann: ihre Zählungen sind Untergrenzen</translation>
    </message>
    <message>
        <source>Double click an area to show it on the map</source>
        <translation>Doppelklick auf eine Fläche zeigt sie in der Karte</translation>
    </message>
    <message>
        <source>Draw area</source>
        <translation>Fläche zeichnen</translation>
    </message>
    <message>
        <source>Draw a compaction area on the 2D map: click to add points; Enter, a double click or a click on the first point closes; Backspace undoes; Esc cancels</source>
        <translation>Eine Verdichtungsfläche in der 2D-Karte zeichnen: Klick setzt Punkte; Enter, Doppelklick oder Klick auf den ersten Punkt schließt; Rücktaste nimmt zurück; Esc bricht ab</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Coverage report…</source>
        <translation>Abdeckungsbericht…</translation>
    </message>
    <message>
        <source>PDF, Veta-style CSV and GeoTIFF of the pass counts, in the site&apos;s projected CRS</source>
        <translation>PDF, CSV im Veta-Stil und GeoTIFF der Übergangszahlen im projizierten KBS der Baustelle</translation>
    </message>
    <message>
        <source>Cancel drawing</source>
        <translation>Zeichnen abbrechen</translation>
    </message>
    <message>
        <source>Area &quot;%1&quot; removed.</source>
        <translation>Fläche „%1“ entfernt.</translation>
    </message>
    <message>
        <source>Design: %1 — %2 alignment(s), %3 boundary(ies)%4</source>
        <translation>Entwurf: %1 — %2 Achse(n), %3 Begrenzung(en)%4</translation>
    </message>
    <message>
        <source> · %1 warning(s): %2</source>
        <translation> · %1 Warnung(en): %2</translation>
    </message>
    <message>
        <source>No design loaded (site configuration &quot;compaction&quot;: {&quot;design&quot;: …}).</source>
        <translation>Kein Entwurf geladen (Baustellenkonfiguration &quot;compaction&quot;: {&quot;design&quot;: …}).</translation>
    </message>
    <message>
        <source>Lift %1 (z %2 … %3 m)</source>
        <translation>Lage %1 (z %2 … %3 m)</translation>
    </message>
    <message>
        <source>%1 (design)</source>
        <translation>%1 (Entwurf)</translation>
    </message>
    <message>
        <source>New compaction area</source>
        <translation>Neue Verdichtungsfläche</translation>
    </message>
    <message>
        <source>Name of the area:</source>
        <translation>Name der Fläche:</translation>
    </message>
    <message>
        <source>Area %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <source>Area &quot;%1&quot; saved to %2.</source>
        <translation>Fläche „%1“ gespeichert in %2.</translation>
    </message>
    <message>
        <source>The drawn area was discarded.</source>
        <translation>Die gezeichnete Fläche wurde verworfen.</translation>
    </message>
    <message>
        <source>Replace area</source>
        <translation>Fläche ersetzen</translation>
    </message>
    <message>
        <source>An area named &quot;%1&quot; exists. Replace it with the new outline?</source>
        <translation>Eine Fläche „%1“ gibt es schon. Durch den neuen Umriss ersetzen?</translation>
    </message>
    <message>
        <source>Coverage report not written.</source>
        <translation>Abdeckungsbericht nicht geschrieben.</translation>
    </message>
    <message>
        <source>Written: %1 (%2.*).</source>
        <translation>Geschrieben: %1 (%2.*).</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Coverage report</source>
        <translation>Abdeckungsbericht</translation>
    </message>
    <message>
        <source>coverage-report.pdf</source>
        <translation>abdeckungsbericht.pdf</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Covered cells within the target passes, % of the range&apos;s band</source>
        <translation>Überfahrene Zellen mit Übergängen im Zielbereich, % des Streifens</translation>
    </message>
    <message>
        <source>Pick a range to outline it on the map; double click to show it</source>
        <translation>Einen Abschnitt wählen umrandet ihn in der Karte; Doppelklick zeigt ihn</translation>
    </message>
    <message>
        <source>Areas</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <source>Stations</source>
        <translation>Stationen</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Ab</translation>
    </message>
    <message>
        <source>No station ranges: the alignment cannot be placed (no EPSG code or worksite frame).</source>
        <translation>Keine Stationsabschnitte: die Achse lässt sich nicht platzieren (kein EPSG-Code oder Baustellenrahmen).</translation>
    </message>
    <message>
        <source>No station ranges without a design alignment.</source>
        <translation>Ohne Achse im Entwurf keine Stationsabschnitte.</translation>
    </message>
    <message>
        <source>Every %1 m along %2 (%3 m left, %4 m right)</source>
        <translation>Alle %1 m entlang %2 (%3 m links, %4 m rechts)</translation>
    </message>
    <message>
        <source>the alignment</source>
        <translation>der Achse</translation>
    </message>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionSession</name>
    <message>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB</source>
        <translation>%1 ist größer als %2 MiB</translation>
    </message>
    <message>
        <source>the design names no EPSG code (CoordinateSystem/@epsgCode): it cannot be placed on the map</source>
        <translation>der Entwurf nennt keinen EPSG-Code (CoordinateSystem/@epsgCode): er kann nicht in die Karte gelegt werden</translation>
    </message>
    <message>
        <source>an area needs a name</source>
        <translation>eine Fläche braucht einen Namen</translation>
    </message>
    <message>
        <source>an area needs at least 3 points</source>
        <translation>eine Fläche braucht mindestens 3 Punkte</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>%1 is not valid JSON (%2): areas not saved</source>
        <translation>%1 ist kein gültiges JSON (%2): Flächen nicht gespeichert</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>no OSYRIS station in this console: no pass counts to report</source>
        <translation>keine OSYRIS-Station in dieser Konsole: keine Übergangszahlen für einen Bericht</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ocu::ControlRoomModel</name>
    <message>
        <source>%1 at %2</source>
        <translation>%1 an %2</translation>
    </message>
    <message>
        <source>not seen since %1</source>
        <translation>nicht gesehen seit %1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>gesperrt</translation>
    </message>
    <message>
        <source>signed in</source>
        <translation>angemeldet</translation>
    </message>
    <message>
        <source>controls machines as %1</source>
        <translation>steuert Maschinen als %1</translation>
    </message>
    <message>
        <source>%1 (this console)</source>
        <translation>%1 (diese Konsole)</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Konsole</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Since</source>
        <translation>Seit</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
</context>
<context>
    <name>ocu::ControlRoomPanel</name>
    <message>
        <source>Waiting for the control-room history…</source>
        <translation>Warte auf die Leitstand-Historie…</translation>
    </message>
    <message>
        <source>Control-room history unavailable since %1: the room as last seen. %2</source>
        <translation>Leitstand-Historie nicht erreichbar seit %1: der Raum wie zuletzt gesehen. %2</translation>
    </message>
</context>
<context>
    <name>ocu::CoverageReport</name>
    <message>
        <source>every lift</source>
        <translation>jede Lage</translation>
    </message>
    <message>
        <source>top view (top-most lift per cell)</source>
        <translation>Draufsicht (oberste Lage je Zelle)</translation>
    </message>
    <message>
        <source>lift %1 (z %2 … %3 m)</source>
        <translation>Lage %1 (z %2 … %3 m)</translation>
    </message>
    <message>
        <source>no pass counts yet</source>
        <translation>noch keine Übergangszahlen</translation>
    </message>
    <message>
        <source>no area named &quot;%1&quot;</source>
        <translation>keine Fläche namens „%1“</translation>
    </message>
    <message>
        <source>the design names no EPSG code: station ranges cannot be placed</source>
        <translation>der Entwurf nennt keinen EPSG-Code: Stationsbereiche können nicht verortet werden</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>PROJ could not convert a cell to EPSG:%1</source>
        <translation>PROJ konnte eine Zelle nicht nach EPSG:%1 umrechnen</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Übergänge</translation>
    </message>
    <message>
        <source> (target)</source>
        <translation> (Ziel)</translation>
    </message>
    <message>
        <source>incomplete</source>
        <translation>unvollständig</translation>
    </message>
    <message>
        <source>vibration on only</source>
        <translation>nur mit Vibration</translation>
    </message>
    <message>
        <source>vibration off only</source>
        <translation>nur ohne Vibration</translation>
    </message>
    <message>
        <source>vibration on or off</source>
        <translation>mit oder ohne Vibration</translation>
    </message>
    <message>
        <source>forward passes only</source>
        <translation>nur Vorwärtsfahrten</translation>
    </message>
    <message>
        <source>backward passes only</source>
        <translation>nur Rückwärtsfahrten</translation>
    </message>
    <message>
        <source>both directions</source>
        <translation>beide Richtungen</translation>
    </message>
    <message>
        <source>speed %1 … %2 m/s</source>
        <translation>Geschwindigkeit %1 … %2 m/s</translation>
    </message>
    <message>
        <source>time %1 … %2</source>
        <translation>Zeit %1 … %2</translation>
    </message>
    <message>
        <source>machines %1 only</source>
        <translation>nur Maschinen %1</translation>
    </message>
    <message>
        <source>Compaction coverage report</source>
        <translation>Verdichtungs-Abdeckungsbericht</translation>
    </message>
    <message>
        <source>Compaction coverage report — %1</source>
        <translation>Verdichtungs-Abdeckungsbericht — %1</translation>
    </message>
    <message>
        <source>Written %1 · %2 · cell %3 m · target %4–%5 passes</source>
        <translation>Erstellt %1 · %2 · Zelle %3 m · Ziel %4–%5 Übergänge</translation>
    </message>
    <message>
        <source>CRS: EPSG:%1 (%2) · design: %3</source>
        <translation>KBS: EPSG:%1 (%2) · Entwurf: %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Machines: %1 · data %2</source>
        <translation>Maschinen: %1 · Daten %2</translation>
    </message>
    <message>
        <source>none known</source>
        <translation>keine bekannt</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>time range not known</source>
        <translation>Zeitraum unbekannt</translation>
    </message>
    <message>
        <source>Filters: %1</source>
        <translation>Filter: %1</translation>
    </message>
    <message>
        <source>%1: z %2 … %3 m</source>
        <translation>%1: z %2 … %3 m</translation>
    </message>
    <message>
        <source>Lifts (thickness %1): %2</source>
        <translation>Lagen (Dicke %1): %2</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>machine %1: %2 slot ranges</source>
        <translation>Maschine %1: %2 Slot-Bereiche</translation>
    </message>
    <message>
        <source>INCOMPLETE: %1 cells may be under-counted: ribbon data that never arrived was given up (%2). Their counts are lower bounds.</source>
        <translation>UNVOLLSTÄNDIG: %1 Zellen sind möglicherweise zu niedrig gezählt: nie eingetroffene Ribbon-Daten wurden aufgegeben (%2). Ihre Zahlen sind Untergrenzen.</translation>
    </message>
    <message>
        <source>Complete: every ribbon slot of every machine was received; no cell is marked incomplete.</source>
        <translation>Vollständig: jeder Ribbon-Slot jeder Maschine ist eingetroffen; keine Zelle ist als unvollständig markiert.</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>covered %</source>
        <translation>überfahren %</translation>
    </message>
    <message>
        <source>under %</source>
        <translation>unter %</translation>
    </message>
    <message>
        <source>at %</source>
        <translation>im Ziel %</translation>
    </message>
    <message>
        <source>over %</source>
        <translation>über %</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>Statistics per area</source>
        <translation>Statistik je Fläche</translation>
    </message>
    <message>
        <source>All counted cells</source>
        <translation>Alle gezählten Zellen</translation>
    </message>
    <message>
        <source>Cells belong to an area when their centre lies inside it. covered = at least one pass; under/at/over the target as % of the area&apos;s cells; min/mean/max over covered cells.</source>
        <translation>Zellen gehören zu einer Fläche, wenn ihr Mittelpunkt darin liegt. überfahren = mindestens ein Übergang; unter/im/über Ziel in % der Zellen der Fläche; min/Mittel/max über die überfahrenen Zellen.</translation>
    </message>
    <message>
        <source>Statistics per station range — %1, %2 m left to %3 m right of the centre line</source>
        <translation>Statistik je Stationsbereich — %1, %2 m links bis %3 m rechts der Achse</translation>
    </message>
    <message>
        <source>Stations</source>
        <translation>Stationen</translation>
    </message>
    <message>
        <source>coverage report written</source>
        <translation>Abdeckungsbericht geschrieben</translation>
    </message>
    <message>
        <source>give &quot;pdf&quot;, &quot;csv&quot; and/or &quot;geotiff&quot; (file names)</source>
        <translation>&quot;pdf&quot;, &quot;csv&quot; und/oder &quot;geotiff&quot; angeben (Dateinamen)</translation>
    </message>
    <message>
        <source>no pass counts yet (no OSYRIS station, or nothing counted)</source>
        <translation>noch keine Übergangszahlen (keine OSYRIS-Station oder nichts gezählt)</translation>
    </message>
    <message>
        <source>no lift %1 (the data has %2)</source>
        <translation>keine Lage %1 (die Daten haben %2)</translation>
    </message>
    <message>
        <source>design CRS: %1</source>
        <translation>KBS des Entwurfs: %1</translation>
    </message>
    <message>
        <source>GDAL has no GTiff driver</source>
        <translation>GDAL hat keinen GTiff-Treiber</translation>
    </message>
    <message>
        <source>PROJ could not convert the raster&apos;s corners</source>
        <translation>PROJ konnte die Ecken des Rasters nicht umrechnen</translation>
    </message>
    <message>
        <source>GDAL cannot create %1: %2</source>
        <translation>GDAL kann %1 nicht anlegen: %2</translation>
    </message>
    <message>
        <source>GDAL does not know EPSG:%1</source>
        <translation>GDAL kennt EPSG:%1 nicht</translation>
    </message>
    <message>
        <source>GDAL cannot write %1: %2</source>
        <translation>GDAL kann %1 nicht schreiben: %2</translation>
    </message>
    <message>
        <source>m²</source>
        <translation>m²</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>area &quot;%1&quot; has fewer than 3 usable vertices</source>
        <translation>Fläche „%1“ hat weniger als 3 brauchbare Eckpunkte</translation>
    </message>
</context>
<context>
    <name>ocu::CrewMessagesPanel</name>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Message to the crew (Enter sends)</source>
        <translation>Nachricht an die Mannschaft (Enter sendet)</translation>
    </message>
    <message>
        <source>Recipient</source>
        <translation>Empfänger</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>Alle Maschinen</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (sending…)</source>
        <translation>%1  → %2: %3 (wird gesendet …)</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (sent)</source>
        <translation>%1  → %2: %3 (gesendet)</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (NOT sent: %4)</source>
        <translation>%1  → %2: %3 (NICHT gesendet: %4)</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchModel</name>
    <message>
        <source>link down</source>
        <translation>Verbindung getrennt</translation>
    </message>
    <message>
        <source>NEEDS ASSIGNMENT</source>
        <translation>BRAUCHT AUFTRAG</translation>
    </message>
    <message>
        <source>Reported assignment: %1</source>
        <translation>Gemeldeter Auftrag: %1</translation>
    </message>
    <message>
        <source>Last request from this console: %1 to way %2 — %3</source>
        <translation>Letzte Anfrage dieser Konsole: %1 zu Weg %2 — %3</translation>
    </message>
    <message>
        <source>no answer yet</source>
        <translation>noch keine Antwort</translation>
    </message>
    <message>
        <source>Detail: %1</source>
        <translation>Detail: %1</translation>
    </message>
    <message>
        <source>The truck asks for work (or was handed back to the FMS).</source>
        <translation>Der Lkw fragt nach Arbeit (oder wurde an das FMS zurückgegeben).</translation>
    </message>
    <message>
        <source>No route: %1</source>
        <translation>Keine Route: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 m over %n way(s) (%2); %3</source>
        <translation>
            <numerusform>%1 m über %n Weg (%2); %3</numerusform>
            <numerusform>%1 m über %n Wege (%2); %3</numerusform>
        </translation>
    </message>
    <message>
        <source>route of the assignment</source>
        <translation>Route des Auftrags</translation>
    </message>
    <message>
        <source>shortest path</source>
        <translation>kürzester Weg</translation>
    </message>
    <message>
        <source>nominal 25 km/h (the truck is slower than 1 m/s)</source>
        <translation>nominell 25 km/h (der Lkw ist langsamer als 1 m/s)</translation>
    </message>
    <message>
        <source>at the reported speed</source>
        <translation>bei der gemeldeten Geschwindigkeit</translation>
    </message>
    <message>
        <source>DispatchingCustodian: who dispatches this truck (only FMS trucks can be assigned)</source>
        <translation>DispatchingCustodian: wer diesen Lkw disponiert (nur FMS-Lkw können Aufträge erhalten)</translation>
    </message>
    <message>
        <source>Truck</source>
        <translation>Lkw</translation>
    </message>
    <message>
        <source>Custodian</source>
        <translation>Disponent</translation>
    </message>
    <message>
        <source>Assignment</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Aufgabe</translation>
    </message>
    <message>
        <source>Destination</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>ETA</source>
        <translation>Ankunft</translation>
    </message>
    <message>
        <source>Payload</source>
        <translation>Nutzlast</translation>
    </message>
    <message>
        <source>In state</source>
        <translation>Im Zustand</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>Weg %1</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Production</source>
        <translation>Produktion</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchPanel</name>
    <message>
        <source>A&amp;uto dispatch</source>
        <translation>A&amp;uto-Disposition</translation>
    </message>
    <message>
        <source>A&amp;uto dispatch ON</source>
        <translation>A&amp;uto-Disposition EIN</translation>
    </message>
    <message>
        <source>Assign every idle FMS truck automatically: empty to the shovel with the shortest queue, loaded to the dump with the shortest queue (Alt+U; switching on asks first).</source>
        <translation>Jeden freien FMS-Lkw automatisch disponieren: leer zum Bagger mit der kürzesten Warteschlange, beladen zur Kippe mit der kürzesten Warteschlange (Alt+U; das Einschalten fragt zuerst).</translation>
    </message>
    <message>
        <source>Switch auto dispatch on?</source>
        <translation>Automatische Disposition einschalten?</translation>
    </message>
    <message>
        <source>Every idle truck the FMS dispatches will be assigned automatically (empty: shortest shovel queue; loaded: shortest dump queue) until you switch it off.</source>
        <translation>Jeder freie Lkw, den das FMS disponiert, erhält automatisch Aufträge (leer: kürzeste Bagger-Warteschlange; beladen: kürzeste Kippen-Warteschlange), bis Sie sie ausschalten.</translation>
    </message>
    <message>
        <source>Auto dispatch ON — last: %1</source>
        <translation>Automatische Disposition EIN — zuletzt: %1</translation>
    </message>
    <message>
        <source>nothing yet</source>
        <translation>noch nichts</translation>
    </message>
    <message>
        <source>Auto dispatch OFF — last: %1</source>
        <translation>Automatische Disposition AUS — zuletzt: %1</translation>
    </message>
    <message>
        <source>&amp;Queues</source>
        <translation>&amp;Warteschlangen</translation>
    </message>
    <message>
        <source>Queues per shovel and dump: trucks at the area and trucks coming to it</source>
        <translation>Warteschlangen je Bagger und Kippe: Lkw im Bereich und Lkw auf dem Weg dorthin</translation>
    </message>
    <message>
        <source>Dispatch panel keys:
Up/Down: choose a truck in the table (Alt+K: go to the table)
F6: next truck that needs an assignment
Alt+T: task, Alt+D: destination (type to search), Alt+M: pick the destination on the 2D map (click an area; Esc cancels)
Ctrl+Enter or Alt+A: assign (re-assigning a truck that has a task asks first)
Alt+R: reset the truck&apos;s assignment (asks first)
Alt+Q: go to the queues per shovel and dump
Alt+U: auto dispatch on/off (switching on asks first)</source>
        <translation>Tasten der Disposition:
Auf/Ab: Lkw in der Tabelle wählen (Alt+L: zur Tabelle)
F6: nächster Lkw, der einen Auftrag braucht
Alt+G: Aufgabe, Alt+Z: Ziel (tippen zum Suchen), Alt+K: Ziel auf der 2D-Karte wählen (Bereich anklicken; Esc bricht ab)
Strg+Eingabe oder Alt+S: zuweisen (ein Lkw mit Auftrag fragt zuerst)
Alt+R: Auftrag des Lkw zurücksetzen (fragt zuerst)
Alt+W: zu den Warteschlangen je Bagger und Kippe
Alt+U: automatische Disposition ein/aus (Einschalten fragt zuerst)</translation>
    </message>
    <message>
        <source>Truc&amp;ks</source>
        <translation>&amp;Lkw</translation>
    </message>
    <message>
        <source>Next needing work (F6)</source>
        <translation>Nächster ohne Arbeit (F6)</translation>
    </message>
    <message>
        <source>Select the next truck that asks for work or was handed back to the FMS.</source>
        <translation>Den nächsten Lkw wählen, der nach Arbeit fragt oder an das FMS zurückgegeben wurde.</translation>
    </message>
    <message>
        <source>&amp;Task</source>
        <translation>Auf&amp;gabe</translation>
    </message>
    <message>
        <source>&amp;Destination</source>
        <translation>&amp;Ziel</translation>
    </message>
    <message>
        <source>Pick on &amp;map</source>
        <translation>Auf der &amp;Karte</translation>
    </message>
    <message>
        <source>Then click a load, dump, crusher, park or fuel area on the 2D map (Esc cancels).</source>
        <translation>Danach einen Lade-, Kipp-, Brecher-, Park- oder Tankbereich auf der 2D-Karte anklicken (Esc bricht ab).</translation>
    </message>
    <message>
        <source>&amp;Assign</source>
        <translation>Zuwei&amp;sen</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>Zu&amp;rücksetzen</translation>
    </message>
    <message>
        <source>Reset the truck&apos;s assignment (HaulTruckAssignmentResetV1); asks first.</source>
        <translation>Den Auftrag des Lkw zurücksetzen (HaulTruckAssignmentResetV1); fragt zuerst.</translation>
    </message>
    <message>
        <source>no areas yet (waiting for the road network)</source>
        <translation>noch keine Bereiche (warte auf das Straßennetz)</translation>
    </message>
    <message>
        <source>no truck needs an assignment</source>
        <translation>kein Lkw braucht einen Auftrag</translation>
    </message>
    <message numerus="yes">
        <source>%n truck(s) need an assignment</source>
        <translation>
            <numerusform>%n Lkw braucht einen Auftrag</numerusform>
            <numerusform>%n Lkw brauchen einen Auftrag</numerusform>
        </translation>
    </message>
    <message>
        <source>No haul truck reports dispatch data yet.</source>
        <translation>Noch kein Muldenkipper meldet Dispositionsdaten.</translation>
    </message>
    <message>
        <source>no dispatch source</source>
        <translation>keine Dispositionsquelle</translation>
    </message>
    <message>
        <source>Re-&amp;assign</source>
        <translation>Neu zuwei&amp;sen</translation>
    </message>
    <message>
        <source>Send %1 to %2 as %3 (Ctrl+Enter)</source>
        <translation>%1 zu %2 als %3 senden (Strg+Eingabe)</translation>
    </message>
    <message>
        <source>preview: %1 → %2 · %3 m</source>
        <translation>Vorschau: %1 → %2 · %3 m</translation>
    </message>
    <message>
        <source>Click an area on the 2D map for %1 (Esc cancels).</source>
        <translation>Einen Bereich auf der 2D-Karte für %1 anklicken (Esc bricht ab).</translation>
    </message>
    <message>
        <source>That map area is not a destination of the road network (no area way %1).</source>
        <translation>Dieser Kartenbereich ist kein Ziel des Straßennetzes (kein Bereichsweg %1).</translation>
    </message>
    <message>
        <source>Destination picked on the map: %1</source>
        <translation>Ziel auf der Karte gewählt: %1</translation>
    </message>
    <message>
        <source>%1 to %2 for %3</source>
        <translation>%1 zu %2 für %3</translation>
    </message>
    <message>
        <source>Re-assign %1?</source>
        <translation>%1 neu zuweisen?</translation>
    </message>
    <message>
        <source>%1 has a %2 assignment (%3 to %4). Replace it with %5?</source>
        <translation>%1 hat einen Auftrag im Zustand %2 (%3 zu %4). Durch %5 ersetzen?</translation>
    </message>
    <message>
        <source>Assign %1</source>
        <translation>%1 zuweisen</translation>
    </message>
    <message>
        <source>Reset %1&apos;s assignment?</source>
        <translation>Auftrag von %1 zurücksetzen?</translation>
    </message>
    <message>
        <source>%1 will drop its %2 assignment (%3) and wait for a new one.</source>
        <translation>%1 verwirft seinen Auftrag im Zustand %2 (%3) und wartet auf einen neuen.</translation>
    </message>
    <message>
        <source>current</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>no task reported</source>
        <translation>keine Aufgabe gemeldet</translation>
    </message>
    <message>
        <source>Reset %1</source>
        <translation>%1 zurücksetzen</translation>
    </message>
    <message>
        <source>%1: sent</source>
        <translation>%1: gesendet</translation>
    </message>
    <message>
        <source>%1: NOT sent — %2</source>
        <translation>%1: NICHT gesendet — %2</translation>
    </message>
    <message>
        <source>NOT sent — %1</source>
        <translation>NICHT gesendet — %1</translation>
    </message>
    <message>
        <source>the truck answered Accepted</source>
        <translation>der Lkw hat mit Accepted geantwortet</translation>
    </message>
    <message>
        <source>the truck answered %1: %2</source>
        <translation>der Lkw hat mit %1 geantwortet: %2</translation>
    </message>
    <message>
        <source>, assignment %1</source>
        <translation>, Auftrag %1</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>Weg %1</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchQueueModel</name>
    <message>
        <source>at: %1</source>
        <translation>dort: %1</translation>
    </message>
    <message>
        <source>coming: %1</source>
        <translation>unterwegs: %1</translation>
    </message>
    <message>
        <source>Shovel (load)</source>
        <translation>Bagger (Laden)</translation>
    </message>
    <message>
        <source>Dump (offload)</source>
        <translation>Kippe (Entladen)</translation>
    </message>
    <message>
        <source>Way %1 on %2. Coming: assigned (Pending/Active) and not yet there; at: the truck reports this area as its way (queued, spotting, loading or dumping).</source>
        <translation>Weg %1 auf %2. Unterwegs: zugewiesen (Pending/Active) und noch nicht dort; dort: der Lkw meldet diesen Bereich als seinen Weg (wartend, ansetzend, ladend oder kippend).</translation>
    </message>
    <message>
        <source>Coming</source>
        <translation>Unterwegs</translation>
    </message>
    <message>
        <source>At area</source>
        <translation>Dort</translation>
    </message>
    <message>
        <source>Trucks</source>
        <translation>Lkw</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>Weg %1</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
</context>
<context>
    <name>ocu::DisplayText</name>
    <message>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Critical</source>
        <translation>Kritisch</translation>
    </message>
    <message>
        <source>link loss</source>
        <translation>Verbindungsverlust</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>health fault</source>
        <translation>Zustandsfehler</translation>
    </message>
    <message>
        <source>diagnostic</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>discrepancy</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <source>control lost</source>
        <translation>Steuerung verloren</translation>
    </message>
    <message>
        <source>text message</source>
        <translation>Textmeldung</translation>
    </message>
    <message>
        <source>operator action</source>
        <translation>Bedienhandlung</translation>
    </message>
    <message>
        <source>info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>low</source>
        <translation>niedrig</translation>
    </message>
    <message>
        <source>medium</source>
        <translation>mittel</translation>
    </message>
    <message>
        <source>high</source>
        <translation>hoch</translation>
    </message>
    <message>
        <source>urgent</source>
        <translation>dringend</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>up</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>beeinträchtigt</translation>
    </message>
    <message>
        <source>down</source>
        <translation>ausgefallen</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>running</source>
        <translation>in Betrieb</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>manuell</translation>
    </message>
    <message>
        <source>autonomous</source>
        <translation>autonom</translation>
    </message>
    <message>
        <source>remote</source>
        <translation>ferngesteuert</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>im Leerlauf</translation>
    </message>
    <message>
        <source>transition</source>
        <translation>Übergang</translation>
    </message>
    <message>
        <source>shutdown</source>
        <translation>abgeschaltet</translation>
    </message>
    <message>
        <source>monitoring</source>
        <translation>beobachtend</translation>
    </message>
    <message>
        <source>this console</source>
        <translation>diese Konsole</translation>
    </message>
    <message>
        <source>another console</source>
        <translation>andere Konsole</translation>
    </message>
    <message>
        <source>denied</source>
        <translation>abgelehnt</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>fault or stopped</source>
        <translation>Fehler oder gestoppt</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>veraltet</translation>
    </message>
</context>
<context>
    <name>ocu::EventLogWidget</name>
    <message>
        <source>Unacknowledged</source>
        <translation>Nicht quittiert</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Quittieren</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation>Alle quittieren</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>CSV exportieren…</translation>
    </message>
    <message>
        <source>Search events…</source>
        <translation>Ereignisse suchen…</translation>
    </message>
    <message>
        <source>All severities</source>
        <translation>Alle Schweregrade</translation>
    </message>
    <message>
        <source>Warning and above</source>
        <translation>Warnung und höher</translation>
    </message>
    <message>
        <source>Alarms only</source>
        <translation>Nur Alarme</translation>
    </message>
    <message>
        <source>Export events</source>
        <translation>Ereignisse exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#d01010&apos;&gt;%1 unacknowledged&lt;/b&gt;</source>
        <translation>&lt;b style=&apos;color:#d01010&apos;&gt;%1 nicht quittiert&lt;/b&gt;</translation>
    </message>
    <message>
        <source>no open alarms</source>
        <translation>keine offenen Alarme</translation>
    </message>
    <message>
        <source>Shelved</source>
        <translation>Zurückgestellte</translation>
    </message>
    <message>
        <source>Shelve</source>
        <translation>Zurückstellen</translation>
    </message>
    <message>
        <source>Unshelve</source>
        <translation>Zurückholen</translation>
    </message>
    <message>
        <source>15 min</source>
        <translation>15 min</translation>
    </message>
    <message>
        <source>1 h</source>
        <translation>1 h</translation>
    </message>
    <message>
        <source>8 h (shift)</source>
        <translation>8 h (Schicht)</translation>
    </message>
    <message>
        <source>Shelve the selected alarms: hidden and not annunciated until the time runs out</source>
        <translation>Gewählte Alarme zurückstellen: ausgeblendet und nicht gemeldet, bis die Zeit abläuft</translation>
    </message>
    <message>
        <source>Show shelved alarms too</source>
        <translation>Auch zurückgestellte Alarme zeigen</translation>
    </message>
    <message>
        <source>New alarms in the last 10 minutes (EEMUA 191: more than 10 is a flood)</source>
        <translation>Neue Alarme in den letzten 10 Minuten (EEMUA 191: mehr als 10 ist eine Alarmflut)</translation>
    </message>
    <message>
        <source>Select an alarm to see its details: the grouped machines, who acknowledged or shelved it, and when.</source>
        <translation>Einen Alarm wählen, um die Einzelheiten zu sehen: die zusammengefassten Maschinen, wer ihn quittiert oder zurückgestellt hat und wann.</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#d01010&apos;&gt;ALARM FLOOD: %1 alarms / 10 min&lt;/b&gt;</source>
        <translation>&lt;b style=&apos;color:#d01010&apos;&gt;ALARMFLUT: %1 Alarme / 10 min&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1 alarms / 10 min</source>
        <translation>%1 Alarme / 10 min</translation>
    </message>
    <message numerus="yes">
        <source>Priority: %1 · raised %2 · %n time(s)</source>
        <translation>
            <numerusform>Priorität: %1 · ausgelöst %2 · %n Mal</numerusform>
            <numerusform>Priorität: %1 · ausgelöst %2 · %n Mal</numerusform>
        </translation>
    </message>
    <message>
        <source>Acknowledged by %1 at %2</source>
        <translation>Quittiert von %1 um %2</translation>
    </message>
    <message>
        <source>Shelved by %1 until %2</source>
        <translation>Zurückgestellt von %1 bis %2</translation>
    </message>
    <message>
        <source>Key: %1</source>
        <translation>Schlüssel: %1</translation>
    </message>
    <message>
        <source>%1 items:</source>
        <translation>%1 Einträge:</translation>
    </message>
</context>
<context>
    <name>ocu::FleetBridge</name>
    <message>
        <source>command &apos;%1&apos; not supported by %2</source>
        <translation>Befehl &apos;%1&apos; wird von %2 nicht unterstützt</translation>
    </message>
    <message>
        <source>%1 io thread not turning</source>
        <translation>E/A-Thread von %1 läuft nicht</translation>
    </message>
    <message>
        <source>%1 io thread has not turned for %2 s (watchdog): its links are degraded, data and commands are held up</source>
        <translation>E/A-Thread von %1 hat seit %2 s nicht gearbeitet (Watchdog): seine Verbindungen sind beeinträchtigt, Daten und Befehle stauen sich</translation>
    </message>
    <message>
        <source>%1 io thread turns again (watchdog)</source>
        <translation>E/A-Thread von %1 läuft wieder (Watchdog)</translation>
    </message>
</context>
<context>
    <name>ocu::FleetDiscrepancyAlarms</name>
    <message>
        <source>%1 autonomous machines of the FMS fleet are missing from the AHS fleet on %2</source>
        <translation>%1 autonome Maschinen der FMS-Flotte fehlen in der AHS-Flotte an %2</translation>
    </message>
    <message>
        <source>%1 machines are listed by both the FMS (manned) and the AHS on %2</source>
        <translation>%1 Maschinen werden sowohl vom FMS (bemannt) als auch vom AHS an %2 geführt</translation>
    </message>
    <message>
        <source>%1 machines have a different HID at the AHS and the FMS on %2</source>
        <translation>%1 Maschinen haben bei AHS und FMS an %2 eine unterschiedliche HID</translation>
    </message>
    <message>
        <source>%1 machines have a different type at the AHS and the FMS on %2</source>
        <translation>%1 Maschinen haben bei AHS und FMS an %2 einen unterschiedlichen Typ</translation>
    </message>
    <message>
        <source>%1 machines have different dimensions at the AHS and the FMS on %2</source>
        <translation>%1 Maschinen haben bei AHS und FMS an %2 unterschiedliche Abmessungen</translation>
    </message>
    <message>
        <source>%1 machines of the AHS are not in the FMS fleet on %2</source>
        <translation>%1 Maschinen des AHS sind an %2 nicht in der FMS-Flotte</translation>
    </message>
    <message>
        <source>Fleet definition discrepancy on %1: %2</source>
        <translation>Abweichung der Flottendefinition bei %1: %2</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… und %1 weitere</translation>
    </message>
</context>
<context>
    <name>ocu::FleetListWidget</name>
    <message>
        <source>Filter machines…</source>
        <translation>Maschinen filtern…</translation>
    </message>
    <message>
        <source>All protocols</source>
        <translation>Alle Protokolle</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Alle Zustände</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Fault / stopped</source>
        <translation>Fehler / gestoppt</translation>
    </message>
    <message>
        <source>Stale / no comms</source>
        <translation>Veraltet / keine Verbindung</translation>
    </message>
    <message>
        <source>Autonomous</source>
        <translation>Autonom</translation>
    </message>
    <message>
        <source>Large rows</source>
        <translation>Große Zeilen</translation>
    </message>
    <message>
        <source>Switch between dense rows (workstation) and large rows (field laptop)</source>
        <translation>Zwischen kompakten Zeilen (Arbeitsplatz) und großen Zeilen (Feld-Laptop) umschalten</translation>
    </message>
    <message>
        <source>Id: %1</source>
        <translation>ID: %1</translation>
    </message>
    <message>
        <source>Name: %1</source>
        <translation>Name: %1</translation>
    </message>
    <message>
        <source>Type: %1</source>
        <translation>Typ: %1</translation>
    </message>
    <message>
        <source>Protocol: %1</source>
        <translation>Protokoll: %1</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>Verbindung: %1</translation>
    </message>
    <message>
        <source>Position: E %1 m, N %2 m, U %3 m</source>
        <translation>Position: E %1 m, N %2 m, U %3 m</translation>
    </message>
    <message>
        <source>WGS84: %1, %2</source>
        <translation>WGS84: %1, %2</translation>
    </message>
    <message>
        <source>Heading: %1°  Speed: %2 km/h</source>
        <translation>Kurs: %1°  Geschw.: %2 km/h</translation>
    </message>
    <message>
        <source>Size: %1 × %2 × %3 m</source>
        <translation>Größe: %1 × %2 × %3 m</translation>
    </message>
    <message>
        <source>Mode: %1 (%2)</source>
        <translation>Modus: %1 (%2)</translation>
    </message>
    <message>
        <source>Stop (reported): %1 %2</source>
        <translation>Stopp (gemeldet): %1 %2</translation>
    </message>
    <message>
        <source>Controller: %1 (%2)</source>
        <translation>Gesteuert von: %1 (%2)</translation>
    </message>
    <message>
        <source>Health: %1 %2</source>
        <translation>Zustand: %1 %2</translation>
    </message>
    <message>
        <source>Centre on map</source>
        <translation>Auf Karte zentrieren</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stoppen</translation>
    </message>
    <message>
        <source>Stop %1 selected</source>
        <translation>%1 ausgewählte stoppen</translation>
    </message>
    <message>
        <source>Details…</source>
        <translation>Details…</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Maschine %1</translation>
    </message>
    <message>
        <source>Work: %1</source>
        <translation>Arbeit: %1</translation>
    </message>
</context>
<context>
    <name>ocu::FleetModel</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Link / age</source>
        <translation>Verbindung / Alter</translation>
    </message>
    <message>
        <source>E (m)</source>
        <translation>E (m)</translation>
    </message>
    <message>
        <source>N (m)</source>
        <translation>N (m)</translation>
    </message>
    <message>
        <source>Lat</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Lon</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Kurs</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschw.</translation>
    </message>
    <message>
        <source>Mode / state</source>
        <translation>Modus / Zustand</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Gesteuert von</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Last message</source>
        <translation>Letzte Meldung</translation>
    </message>
    <message>
        <source>STOPPED</source>
        <translation>GESTOPPT</translation>
    </message>
    <message>
        <source>running</source>
        <translation>in Betrieb</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>this OCU</source>
        <translation>diese Konsole</translation>
    </message>
    <message>
        <source>up</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>beeinträchtigt</translation>
    </message>
    <message>
        <source>down</source>
        <translation>ausgefallen</translation>
    </message>
</context>
<context>
    <name>ocu::HandoffBanner</name>
    <message>
        <source>Accept</source>
        <translation>Annehmen</translation>
    </message>
    <message>
        <source>Deny</source>
        <translation>Ablehnen</translation>
    </message>
    <message>
        <source>Ask for hand-off</source>
        <translation>Übergabe erbitten</translation>
    </message>
    <message>
        <source>Withdraw</source>
        <translation>Zurückziehen</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Hand control of this vehicle to the console that asks</source>
        <translation>Steuerung dieses Fahrzeugs an die anfragende Konsole übergeben</translation>
    </message>
    <message>
        <source>Keep control; the console that asks is told</source>
        <translation>Steuerung behalten; die anfragende Konsole wird benachrichtigt</translation>
    </message>
    <message>
        <source>Reason the holder&apos;s operator sees</source>
        <translation>Grund, den der Bediener des Inhabers sieht</translation>
    </message>
    <message>
        <source>Console %1 asks for control of %2 (authority %3).</source>
        <translation>Konsole %1 fordert die Steuerung von %2 an (Autorität %3).</translation>
    </message>
    <message>
        <source>Reason: %1</source>
        <translation>Grund: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n more request(s) waiting after this one.</source>
        <translation>
            <numerusform>Nach dieser wartet noch %n Anfrage.</numerusform>
            <numerusform>Nach dieser warten noch %n Anfragen.</numerusform>
        </translation>
    </message>
    <message>
        <source>No time limit: the vehicle waits for your answer.</source>
        <translation>Keine Frist: das Fahrzeug wartet auf Ihre Antwort.</translation>
    </message>
    <message numerus="yes">
        <source>Answer within %n s, else the vehicle refuses it (timeout).</source>
        <translation>
            <numerusform>Antworten Sie binnen %n s, sonst lehnt das Fahrzeug ab (Zeitüberschreitung).</numerusform>
            <numerusform>Antworten Sie binnen %n s, sonst lehnt das Fahrzeug ab (Zeitüberschreitung).</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is held by console %2 (authority %3). Ask its operator to hand it over:</source>
        <translation>%1 wird von Konsole %2 gesteuert (Autorität %3). Dessen Bediener um Übergabe bitten:</translation>
    </message>
    <message>
        <source>%1 is held by %2 (authority %3) and offers no Enhanced Access Control: asking takes control only with a higher authority than the holder&apos;s (ordinary pre-emption, authority %4 here).</source>
        <translation>%1 wird von %2 gesteuert (Autorität %3) und bietet keine erweiterte Zugriffskontrolle (Enhanced Access Control): eine Anfrage übernimmt die Steuerung nur mit höherer Autorität als der des Inhabers (normale Verdrängung, hier Autorität %4).</translation>
    </message>
    <message>
        <source>Waiting for the holder&apos;s answer</source>
        <translation>Warte auf die Antwort des Inhabers</translation>
    </message>
    <message>
        <source>Granted: taking control</source>
        <translation>Gewährt: Steuerung wird übernommen</translation>
    </message>
    <message>
        <source>Control handed over</source>
        <translation>Steuerung übergeben</translation>
    </message>
    <message>
        <source>Denied</source>
        <translation>Abgelehnt</translation>
    </message>
    <message>
        <source>No answer in time</source>
        <translation>Keine Antwort in der Frist</translation>
    </message>
    <message>
        <source>Refused</source>
        <translation>Verweigert</translation>
    </message>
    <message>
        <source>Withdrawn</source>
        <translation>Zurückgezogen</translation>
    </message>
    <message>
        <source>Requesting control (ordinary pre-emption)</source>
        <translation>Steuerung wird angefordert (normale Verdrängung)</translation>
    </message>
    <message>
        <source>Hand-off of %1: %2.</source>
        <translation>Übergabe von %1: %2.</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>Warten</translation>
    </message>
    <message>
        <source>Not yet: the request stays and the decision time starts again; the console that asks is told to wait</source>
        <translation>Noch nicht: die Anfrage bleibt, die Entscheidungszeit beginnt neu; die anfragende Konsole wird gebeten zu warten</translation>
    </message>
    <message>
        <source>You asked it to wait; its console keeps the request up.</source>
        <translation>Sie haben um Warten gebeten; die Konsole hält die Anfrage aufrecht.</translation>
    </message>
    <message>
        <source>The holder asks you to wait; the request is kept up</source>
        <translation>Der Inhaber bittet Sie zu warten; die Anfrage bleibt bestehen</translation>
    </message>
    <message>
        <source>%1 (console %2) asks for control of %3 (authority %4).</source>
        <translation>%1 (Konsole %2) fordert die Steuerung von %3 an (Autorität %4).</translation>
    </message>
    <message>
        <source>%1 is held by %2 (console %3, authority %4). Ask them to hand it over:</source>
        <translation>%1 wird von %2 gesteuert (Konsole %3, Autorität %4). Um Übergabe bitten:</translation>
    </message>
</context>
<context>
    <name>ocu::HardwareStopButton</name>
    <message>
        <source>STOP button unavailable: the joystick subsystem did not start (%1)</source>
        <translation>STOP-Taster nicht verfügbar: das Joystick-Subsystem ist nicht gestartet (%1)</translation>
    </message>
    <message>
        <source>button %1 of any joystick</source>
        <translation>Taste %1 eines beliebigen Joysticks</translation>
    </message>
    <message>
        <source>button %1 of &quot;%2&quot;</source>
        <translation>Taste %1 von „%2“</translation>
    </message>
    <message>
        <source>STOP button connected: %1 (%2)</source>
        <translation>STOP-Taster verbunden: %1 (%2)</translation>
    </message>
    <message>
        <source>STOP button disconnected: %1; STOP ALL stays available on the console</source>
        <translation>STOP-Taster getrennt: %1; ALLE STOPPEN bleibt an der Konsole verfügbar</translation>
    </message>
</context>
<context>
    <name>ocu::HoldToConfirmButton</name>
    <message>
        <source>Press and hold to confirm</source>
        <translation>Zum Bestätigen gedrückt halten</translation>
    </message>
</context>
<context>
    <name>ocu::IlluminationBar</name>
    <message>
        <source>Head</source>
        <translation>Front</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Fahrl.</translation>
    </message>
    <message>
        <source>◀ Turn</source>
        <translation>◀ Blink</translation>
    </message>
    <message>
        <source>Turn ▶</source>
        <translation>Blink ▶</translation>
    </message>
    <message>
        <source>Brake</source>
        <translation>Brems</translation>
    </message>
    <message>
        <source>IR</source>
        <translation>IR</translation>
    </message>
    <message>
        <source>Lights:</source>
        <translation>Licht:</translation>
    </message>
    <message>
        <source>Lights: not offered by this vehicle</source>
        <translation>Licht: von diesem Fahrzeug nicht angeboten</translation>
    </message>
    <message>
        <source>%1: this vehicle has none</source>
        <translation>%1: an diesem Fahrzeug nicht vorhanden</translation>
    </message>
    <message>
        <source>%1: not reported yet</source>
        <translation>%1: noch nicht gemeldet</translation>
    </message>
    <message>
        <source>%1: on, as the vehicle reports (click to switch off)</source>
        <translation>%1: an, laut Fahrzeug (Klick schaltet aus)</translation>
    </message>
    <message>
        <source>%1: off, as the vehicle reports (click to switch on)</source>
        <translation>%1: aus, laut Fahrzeug (Klick schaltet ein)</translation>
    </message>
</context>
<context>
    <name>ocu::ImageView</name>
    <message>
        <source>3D view unavailable</source>
        <translation>3D-Ansicht nicht verfügbar</translation>
    </message>
</context>
<context>
    <name>ocu::IsoBridge</name>
    <message>
        <source>connecting</source>
        <translation>Verbindungsaufbau</translation>
    </message>
    <message>
        <source>ISO 23725: a link could not start (see the event log)</source>
        <translation>ISO 23725: eine Verbindung konnte nicht starten (siehe Ereignisprotokoll)</translation>
    </message>
    <message>
        <source>ISO 23725 link %1 down: %2</source>
        <translation>ISO 23725-Verbindung %1 ausgefallen: %2</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop %2%3</source>
        <translation>AHS %1 meldet Gesamtstopp %2%3</translation>
    </message>
    <message>
        <source> (issued by another system)</source>
        <translation> (von einem anderen System ausgelöst)</translation>
    </message>
    <message>
        <source>all-stop</source>
        <translation>Gesamtstopp</translation>
    </message>
    <message>
        <source>no active diagnostics</source>
        <translation>keine aktive Diagnose</translation>
    </message>
    <message>
        <source>diagnostics %1</source>
        <translation>Diagnose %1</translation>
    </message>
    <message>
        <source>fuel %1 %</source>
        <translation>Kraftstoff %1 %</translation>
    </message>
    <message>
        <source>no ISO 23725 link configured</source>
        <translation>keine ISO 23725-Verbindung konfiguriert</translation>
    </message>
    <message>
        <source>%1: unknown ISO 23725 link &quot;%2&quot;</source>
        <translation>%1: unbekannte ISO 23725-Verbindung „%2“</translation>
    </message>
    <message>
        <source>%1 on way %2</source>
        <translation>%1 auf Weg %2</translation>
    </message>
    <message>
        <source>payload %1 t</source>
        <translation>Nutzlast %1 t</translation>
    </message>
    <message>
        <source>loaded</source>
        <translation>beladen</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <source>body raised</source>
        <translation>Mulde angehoben</translation>
    </message>
    <message>
        <source>park brake on</source>
        <translation>Feststellbremse an</translation>
    </message>
    <message>
        <source>assignment %1</source>
        <translation>Auftrag %1</translation>
    </message>
    <message>
        <source> (%1 at way %2)</source>
        <translation> (%1 an Weg %2)</translation>
    </message>
    <message>
        <source>last dump %1 t at way %2</source>
        <translation>letzte Entladung %1 t an Weg %2</translation>
    </message>
    <message>
        <source>last dump at way %1</source>
        <translation>letzte Entladung an Weg %1</translation>
    </message>
    <message>
        <source>ISO 23725 stack stopped</source>
        <translation>ISO 23725-Stack gestoppt</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop active</source>
        <translation>AHS %1 meldet Gesamtstopp aktiv</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop inactive</source>
        <translation>AHS %1 meldet Gesamtstopp inaktiv</translation>
    </message>
    <message>
        <source>unknown ISO 23725 machine %1</source>
        <translation>unbekannte ISO 23725-Maschine %1</translation>
    </message>
    <message>
        <source>assignment</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <source>assignment refused: %1 has not reported its DispatchingCustodian yet</source>
        <translation>Auftrag abgelehnt: %1 hat seinen DispatchingCustodian noch nicht gemeldet</translation>
    </message>
    <message>
        <source>assignment refused: %1 is dispatched by the %2 (DispatchingCustodian %2)</source>
        <translation>Auftrag abgelehnt: %1 wird vom %2 disponiert (DispatchingCustodian %2)</translation>
    </message>
    <message>
        <source>implausible position ignored (%1 so far): %2</source>
        <translation>unplausible Position verworfen (bisher %1): %2</translation>
    </message>
    <message>
        <source>ISO 23725 link %1, machine %2: position ignored, %3 (lat %4, lon %5, speed %6 km/h); last good position kept (counted in rx.implausible.%7; one warning per machine and cause every 30 s)</source>
        <translation>ISO 23725-Verbindung %1, Maschine %2: Position verworfen, %3 (Breite %4, Länge %5, Geschwindigkeit %6 km/h); letzte gute Position beibehalten (gezählt in rx.implausible.%7; eine Warnung je Maschine und Ursache alle 30 s)</translation>
    </message>
    <message>
        <source>%1 refused: ISO 23725 link %2 is down%3; nothing sent</source>
        <translation>%1 abgelehnt: ISO 23725-Verbindung %2 ist ausgefallen%3; nichts gesendet</translation>
    </message>
    <message>
        <source>%1 refused: ISO 23725 link %2 is not connected%3; nothing sent</source>
        <translation>%1 abgelehnt: ISO 23725-Verbindung %2 ist nicht verbunden%3; nichts gesendet</translation>
    </message>
    <message>
        <source>all-stop Apply</source>
        <translation>Gesamtstopp Apply</translation>
    </message>
    <message>
        <source>all-stop Remove</source>
        <translation>Gesamtstopp Remove</translation>
    </message>
    <message>
        <source>the ISO 23725 stack is not running; nothing sent</source>
        <translation>der ISO 23725-Stack läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>unknown ISO 23725 machine</source>
        <translation>unbekannte ISO 23725-Maschine</translation>
    </message>
    <message>
        <source>%1: &quot;id&quot; must name an ISO 23725 machine</source>
        <translation>%1: „id“ muss eine ISO 23725-Maschine bezeichnen</translation>
    </message>
    <message>
        <source>assign refused: %1; nothing sent</source>
        <translation>Zuweisung abgelehnt: %1; nichts gesendet</translation>
    </message>
    <message>
        <source>no task given</source>
        <translation>keine Aufgabe angegeben</translation>
    </message>
</context>
<context>
    <name>ocu::IsoDispatchSource</name>
    <message>
        <source>the ISO 23725 bridge is gone</source>
        <translation>die ISO 23725-Brücke ist nicht mehr vorhanden</translation>
    </message>
    <message>
        <source>unknown truck</source>
        <translation>unbekannter Lkw</translation>
    </message>
    <message>
        <source>no active assignment</source>
        <translation>kein aktiver Auftrag</translation>
    </message>
    <message>
        <source>the truck has not reported its way</source>
        <translation>der Lkw hat seinen Weg nicht gemeldet</translation>
    </message>
    <message>
        <source>no MapConnectivityV1 from the AHS yet</source>
        <translation>noch keine MapConnectivityV1 vom AHS</translation>
    </message>
    <message>
        <source>unknown truck or another AHS&apos;s area</source>
        <translation>unbekannter Lkw oder Bereich eines anderen AHS</translation>
    </message>
</context>
<context>
    <name>ocu::JausBridge</name>
    <message>
        <source>JAUS: %1</source>
        <translation>JAUS: %1</translation>
    </message>
    <message>
        <source>searching for subsystems</source>
        <translation>Suche nach Subsystemen</translation>
    </message>
    <message numerus="yes">
        <source>%n subsystem(s) up</source>
        <translation>
            <numerusform>%n Subsystem aktiv</numerusform>
            <numerusform>%n Subsysteme aktiv</numerusform>
        </translation>
    </message>
    <message>
        <source>no subsystem answering</source>
        <translation>kein Subsystem antwortet</translation>
    </message>
    <message>
        <source>JAUS: no group socket (%1 held by another process)</source>
        <translation>JAUS: kein Gruppen-Socket (Port %1 von einem anderen Prozess belegt)</translation>
    </message>
    <message>
        <source>JAUS: no group socket (%1)</source>
        <translation>JAUS: kein Gruppen-Socket (%1)</translation>
    </message>
    <message>
        <source>emergency</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>this console (%1)</source>
        <translation>diese Konsole (%1)</translation>
    </message>
    <message>
        <source>%1 refused: this console&apos;s JAUS role is MONITOR</source>
        <translation>%1: abgelehnt, JAUS-Rolle dieser Konsole ist MONITOR</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>clear emergency</source>
        <translation>Not-Halt aufheben</translation>
    </message>
    <message>
        <source>drive</source>
        <translation>Fahren</translation>
    </message>
    <message>
        <source>drive refused: this console does not control %1</source>
        <translation>Fahren abgelehnt: diese Konsole steuert %1 nicht</translation>
    </message>
    <message>
        <source>%1: &quot;id&quot; must name a JAUS machine such as &quot;jaus:101&quot;</source>
        <translation>%1: &quot;id&quot; muss eine JAUS-Maschine bezeichnen, z. B. &quot;jaus:101&quot;</translation>
    </message>
    <message>
        <source>drive: &quot;duration&quot; must be between 0 and 60 seconds</source>
        <translation>drive: &quot;duration&quot; muss zwischen 0 und 60 Sekunden liegen</translation>
    </message>
    <message>
        <source>drive: effort must be within ±100 %</source>
        <translation>drive: Stellwert muss innerhalb von ±100 % liegen</translation>
    </message>
    <message>
        <source>%1 reports EMERGENCY</source>
        <translation>%1 meldet NOT-HALT</translation>
    </message>
    <message>
        <source>%1 reports %2: emergency cleared</source>
        <translation>%1 meldet %2: Not-Halt aufgehoben</translation>
    </message>
    <message>
        <source>no emergency</source>
        <translation>kein Not-Halt</translation>
    </message>
    <message>
        <source>%1 confirms control by this console</source>
        <translation>%1 bestätigt die Steuerung durch diese Konsole</translation>
    </message>
    <message>
        <source>%1 refuses control: insufficient authority</source>
        <translation>%1 verweigert die Steuerung: unzureichende Autorität</translation>
    </message>
    <message>
        <source>%1 reports control released</source>
        <translation>%1 meldet Steuerung freigegeben</translation>
    </message>
    <message>
        <source>JAUS stack stopped</source>
        <translation>JAUS-Stack gestoppt</translation>
    </message>
    <message>
        <source>%1 refused: %2 has not been heard on the JAUS link; nothing sent</source>
        <translation>%1 abgelehnt: %2 wurde auf der JAUS-Verbindung nicht empfangen; nichts gesendet</translation>
    </message>
    <message>
        <source>%1 refused: the link to %2 is down; nothing sent</source>
        <translation>%1 abgelehnt: die Verbindung zu %2 ist ausgefallen; nichts gesendet</translation>
    </message>
    <message>
        <source>the JAUS stack is not running; nothing sent</source>
        <translation>der JAUS-Stack läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>emergency stop refused by this console&apos;s JAUS role</source>
        <translation>Not-Halt von der JAUS-Rolle dieser Konsole abgelehnt</translation>
    </message>
    <message>
        <source>no JAUS vehicle known and the JAUS stack is not running; nothing sent</source>
        <translation>kein JAUS-Fahrzeug bekannt und der JAUS-Stack läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>not a JAUS machine</source>
        <translation>keine JAUS-Maschine</translation>
    </message>
    <message>
        <source>clear emergency refused: this console&apos;s JAUS role has no command rights</source>
        <translation>Not-Halt aufheben abgelehnt: die JAUS-Rolle dieser Konsole hat keine Befehlsrechte</translation>
    </message>
    <message>
        <source>this console controls no JAUS vehicle: nothing to release</source>
        <translation>diese Konsole steuert kein JAUS-Fahrzeug: nichts freizugeben</translation>
    </message>
    <message>
        <source>drive refused: the JAUS stack is not running; nothing sent</source>
        <translation>Fahren abgelehnt: der JAUS-Stack läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>drive refused: no drive session open for %1 (a session starts through the command gate)</source>
        <translation>Fahren abgelehnt: keine Fahrsitzung für %1 offen (eine Sitzung beginnt über die Befehlsfreigabe)</translation>
    </message>
    <message>
        <source>drive demand handed to the drive stream</source>
        <translation>Fahrvorgabe an den Fahrdatenstrom übergeben</translation>
    </message>
    <message>
        <source>the JAUS stack is not running; no zero drive commands sent</source>
        <translation>der JAUS-Stack läuft nicht; keine Null-Fahrbefehle gesendet</translation>
    </message>
    <message>
        <source>zero drive commands handed to the stack</source>
        <translation>Null-Fahrbefehle an den Stack übergeben</translation>
    </message>
    <message>
        <source>pan-tilt</source>
        <translation>Schwenken/Neigen</translation>
    </message>
    <message>
        <source>pan-tilt refused: the JAUS stack is not running; nothing sent</source>
        <translation>Schwenken/Neigen abgelehnt: der JAUS-Stack läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>pan-tilt refused: this console does not control %1</source>
        <translation>Schwenken/Neigen abgelehnt: diese Konsole steuert %1 nicht</translation>
    </message>
    <message>
        <source>pan-tilt refused: the rates must be finite numbers</source>
        <translation>Schwenken/Neigen abgelehnt: die Raten müssen endliche Zahlen sein</translation>
    </message>
    <message>
        <source>pan-tilt demand handed to the stack</source>
        <translation>Schwenk-/Neigevorgabe an den Stack übergeben</translation>
    </message>
    <message>
        <source>implausible pose ignored (%1 so far): %2</source>
        <translation>unplausible Lage verworfen (bisher %1): %2</translation>
    </message>
    <message>
        <source>JAUS subsystem %1: pose ignored, %2 (east %3 m, north %4 m, speed %5 m/s); last good pose kept (counted in rx.implausible.%6; one warning per vehicle and cause every 30 s)</source>
        <translation>JAUS-Subsystem %1: Lage verworfen, %2 (Ost %3 m, Nord %4 m, Geschwindigkeit %5 m/s); letzte gute Lage beibehalten (gezählt in rx.implausible.%6; eine Warnung je Fahrzeug und Ursache alle 30 s)</translation>
    </message>
    <message>
        <source>%1 reports the mission %2</source>
        <translation>%1 meldet die Mission %2</translation>
    </message>
    <message>
        <source>last reported: odometer %1 m, trip %2 m</source>
        <translation>zuletzt gemeldet: Gesamtstrecke %1 m, Tagesstrecke %2 m</translation>
    </message>
    <message>
        <source>drive refused: %1 reports the emergency platform state; nothing sent</source>
        <translation>Fahren abgelehnt: %1 meldet den Plattform-Notzustand; nichts gesendet</translation>
    </message>
</context>
<context>
    <name>ocu::JausControlPanel</name>
    <message>
        <source>Release all</source>
        <translation>Alle freigeben</translation>
    </message>
    <message>
        <source>This console: %1 [%2] · authority %3</source>
        <translation>Diese Konsole: %1 [%2] · Autorität %3</translation>
    </message>
    <message>
        <source>This console: %1 [%2] · MONITOR role: commands are disabled</source>
        <translation>Diese Konsole: %1 [%2] · Rolle MONITOR: Befehle deaktiviert</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Beobachten</translation>
    </message>
    <message>
        <source>Select this vehicle to watch it (no control)</source>
        <translation>Dieses Fahrzeug zur Beobachtung auswählen (keine Steuerung)</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>Steuern</translation>
    </message>
    <message>
        <source>Request control with this console&apos;s authority</source>
        <translation>Steuerung mit der Autorität dieser Konsole anfordern</translation>
    </message>
    <message>
        <source>Release</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <source>Release control of this vehicle</source>
        <translation>Steuerung dieses Fahrzeugs freigeben</translation>
    </message>
    <message>
        <source>No machine selected.
Select one in the fleet list, in the table above or on the map (click, or Tab to the list and use the arrow keys) to see its details here.</source>
        <translation>Keine Maschine ausgewählt.
Wählen Sie eine in der Flottenliste, in der Tabelle oben oder auf der Karte aus (Klick, oder mit Tab zur Liste und den Pfeiltasten), um hier ihre Details zu sehen.</translation>
    </message>
</context>
<context>
    <name>ocu::JausPlatform</name>
    <message>
        <source>standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>training</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>maintenance</source>
        <translation>Wartung</translation>
    </message>
    <message>
        <source>program mode %1</source>
        <translation>Programmmodus %1</translation>
    </message>
    <message>
        <source>initialize</source>
        <translation>Initialisierung</translation>
    </message>
    <message>
        <source>operational</source>
        <translation>betriebsbereit</translation>
    </message>
    <message>
        <source>shutdown</source>
        <translation>Abschaltung</translation>
    </message>
    <message>
        <source>system abort</source>
        <translation>Systemabbruch</translation>
    </message>
    <message>
        <source>emergency</source>
        <translation>Notzustand</translation>
    </message>
    <message>
        <source>render useless</source>
        <translation>unbrauchbar machen</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>Zustand %1</translation>
    </message>
    <message>
        <source>headlights</source>
        <translation>Scheinwerfer</translation>
    </message>
    <message>
        <source>left turn signal</source>
        <translation>Blinker links</translation>
    </message>
    <message>
        <source>right turn signal</source>
        <translation>Blinker rechts</translation>
    </message>
    <message>
        <source>running lights</source>
        <translation>Tagfahrlicht</translation>
    </message>
    <message>
        <source>brake lights</source>
        <translation>Bremslicht</translation>
    </message>
    <message>
        <source>IR source</source>
        <translation>IR-Strahler</translation>
    </message>
</context>
<context>
    <name>ocu::JausSubsystemModel</name>
    <message>
        <source>unnamed</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>%1 · %2 s</source>
        <translation>%1 · %2 s</translation>
    </message>
    <message>
        <source>this console (%1)</source>
        <translation>diese Konsole (%1)</translation>
    </message>
    <message>
        <source>%1.%2.%3 (%4)</source>
        <translation>%1.%2.%3 (%4)</translation>
    </message>
    <message>
        <source>nobody</source>
        <translation>niemand</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source> · EMERGENCY</source>
        <translation> · EMERGENCY</translation>
    </message>
    <message>
        <source>Vehicle [ID]</source>
        <translation>Fahrzeug [ID]</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>Controlled by</source>
        <translation>Gesteuert von</translation>
    </message>
    <message>
        <source>Management</source>
        <translation>Verwaltung</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Actions</source>
        <translation>Aktionen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>operator at console (JAUS authority)</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1, JAUS %2</source>
        <comment>operator at console, JAUS ID of its component</comment>
        <translation>%1, JAUS %2</translation>
    </message>
</context>
<context>
    <name>ocu::JausVehicleBridge</name>
    <message>
        <source>pan-tilt: this vehicle link drives no pan-tilt; nothing sent</source>
        <translation>Schwenken/Neigen: diese Fahrzeugverbindung steuert keinen Schwenk-Neige-Kopf; nichts gesendet</translation>
    </message>
</context>
<context>
    <name>ocu::JoystickMappingDialog</name>
    <message>
        <source>Invert</source>
        <translation>Umkehren</translation>
    </message>
    <message>
        <source>Joystick mapping</source>
        <translation>Joystick-Belegung</translation>
    </message>
    <message>
        <source>Detect…</source>
        <translation>Erkennen…</translation>
    </message>
    <message>
        <source>Then push the stick fully forward</source>
        <translation>Danach den Stick ganz nach vorn drücken</translation>
    </message>
    <message>
        <source>Then push the stick fully right</source>
        <translation>Danach den Stick ganz nach rechts drücken</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <source>Forward / reverse</source>
        <translation>Vorwärts / rückwärts</translation>
    </message>
    <message>
        <source>Turn</source>
        <translation>Lenken</translation>
    </message>
    <message>
        <source>Dead zone</source>
        <translation>Totzone</translation>
    </message>
    <message>
        <source>Move the stick to see its axes.</source>
        <translation>Stick bewegen, um seine Achsen zu sehen.</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Achse %1</translation>
    </message>
    <message>
        <source>Push the stick fully forward and hold it…</source>
        <translation>Stick ganz nach vorn drücken und halten…</translation>
    </message>
    <message>
        <source>Push the stick fully to the right and hold it…</source>
        <translation>Stick ganz nach rechts drücken und halten…</translation>
    </message>
    <message>
        <source>%1: axis %2%3 — release the stick.</source>
        <translation>%1: Achse %2%3 – Stick loslassen.</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <source>, inverted</source>
        <translation>, umgekehrt</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Demand: forward %1 %, turn %2 %</source>
        <translation>Vorgabe: vorwärts %1 %, lenken %2 %</translation>
    </message>
    <message>
        <source>Forward and turn need two different axes.</source>
        <translation>Vorwärts und Lenken brauchen zwei verschiedene Achsen.</translation>
    </message>
</context>
<context>
    <name>ocu::LegendOverlay</name>
    <message>
        <source>Passes</source>
        <translation>Überfahrten</translation>
    </message>
</context>
<context>
    <name>ocu::LinkIndicator</name>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>up</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>beeinträchtigt</translation>
    </message>
    <message>
        <source>down</source>
        <translation>ausgefallen</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1: no input rejected</source>
        <translation>%1: keine Eingabe verworfen</translation>
    </message>
    <message>
        <source>%1: %2 inputs rejected</source>
        <translation>%1: %2 Eingaben verworfen</translation>
    </message>
</context>
<context>
    <name>ocu::LockScreen</name>
    <message>
        <source>Console locked</source>
        <translation>Konsole gesperrt</translation>
    </message>
    <message>
        <source>The picture is read-only. STOP ALL stays active (F12).</source>
        <translation>Das Bild ist schreibgeschützt. ALLE STOPPEN bleibt aktiv (F12).</translation>
    </message>
    <message>
        <source>&amp;Unlock…</source>
        <translation>&amp;Entsperren…</translation>
    </message>
    <message>
        <source>S&amp;witch operator…</source>
        <translation>Bediener &amp;wechseln…</translation>
    </message>
</context>
<context>
    <name>ocu::MainWindow</name>
    <message>
        <source>Operator Control Unit</source>
        <translation>Bedienstation</translation>
    </message>
    <message>
        <source>Fleet</source>
        <translation>Flotte</translation>
    </message>
    <message>
        <source>Site map (2D)</source>
        <translation>Lageplan (2D)</translation>
    </message>
    <message>
        <source>Site 3D</source>
        <translation>Baustelle 3D</translation>
    </message>
    <message>
        <source>JAUS control</source>
        <translation>JAUS-Steuerung</translation>
    </message>
    <message>
        <source>Teleop</source>
        <translation>Fernsteuerung</translation>
    </message>
    <message>
        <source>Pass counts</source>
        <translation>Verdichtungsübergänge</translation>
    </message>
    <message>
        <source>Event log</source>
        <translation>Ereignisprotokoll</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Startet…</translation>
    </message>
    <message>
        <source>Safety</source>
        <translation>Sicherheit</translation>
    </message>
    <message>
        <source>STOP ALL</source>
        <translation>ALLE STOPPEN</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Save &amp;screenshot…</source>
        <translation>Bildschirmfoto &amp;speichern…</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Bildschirmfoto speichern</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Night palette</source>
        <translation>&amp;Nachtpalette</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;Über</translation>
    </message>
    <message>
        <source>About the Operator Control Unit</source>
        <translation>Über die Bedienstation</translation>
    </message>
    <message>
        <source>No unacknowledged alarms</source>
        <translation>Keine unquittierten Alarme</translation>
    </message>
    <message numerus="yes">
        <source>%n unacknowledged alarm(s)</source>
        <translation>
            <numerusform>%n unquittierter Alarm</numerusform>
            <numerusform>%n unquittierte Alarme</numerusform>
        </translation>
    </message>
    <message>
        <source>F12 or Ctrl+Shift+Space: STOP ALL</source>
        <translation>F12 oder Strg+Umschalt+Leertaste: ALLE STOPPEN</translation>
    </message>
    <message>
        <source>Teleop panel: W/A/S/D or arrows with the dead-man key held; Space or Esc: emergency stop</source>
        <translation>Fernsteuerung: W/A/S/D oder Pfeiltasten bei gehaltener Totmanntaste; Leertaste oder Esc: Not-Halt</translation>
    </message>
    <message>
        <source>Dispatch: F6 next truck needing work, Alt+T task, Alt+D destination, Alt+M pick on map, Ctrl+Enter assign, Alt+R reset</source>
        <translation>Disposition: F6 nächster Lkw ohne Auftrag, Alt+G Aufgabe, Alt+Z Ziel, Alt+K auf der Karte wählen, Strg+Eingabe zuweisen, Alt+R zurücksetzen</translation>
    </message>
    <message>
        <source>Site map: arrows pan, +/- or wheel zoom (about the cursor), F follow the selected machine, Home whole site, Shift+Home the fleet, S the selection, A the area under the cursor, C centre; double-click selects; click an edge arrow to go to machines outside the view</source>
        <translation>Lageplan: Pfeiltasten verschieben, +/- oder Mausrad zoomen (um den Mauszeiger), F folgt der ausgewählten Maschine, Pos1 ganzes Gelände, Umschalt+Pos1 die Flotte, S die Auswahl, A die Fläche unter dem Mauszeiger, C zentrieren; Doppelklick wählt aus; ein Randpfeil führt zu Maschinen außerhalb der Ansicht</translation>
    </message>
    <message>
        <source>Ctrl+Shift+N: night palette</source>
        <translation>Strg+Umschalt+N: Nachtpalette</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P: save a screenshot</source>
        <translation>Strg+Umschalt+P: Bildschirmfoto speichern</translation>
    </message>
    <message>
        <source>Go to a panel (raises it and puts the keyboard focus in it):</source>
        <translation>Zu einem Feld (holt es nach vorn und setzt den Tastaturfokus hinein):</translation>
    </message>
    <message>
        <source>Tab / Shift+Tab: next / previous control in a panel; arrows move in lists and tables; Space or Enter presses the focused button</source>
        <translation>Tab / Umschalt+Tab: nächstes / vorheriges Bedienelement eines Felds; Pfeiltasten bewegen in Listen und Tabellen; Leertaste oder Eingabe drückt die fokussierte Schaltfläche</translation>
    </message>
    <message>
        <source>See docs/keyboard.md for the full list.</source>
        <translation>Die vollständige Liste steht in docs/keyboard.md.</translation>
    </message>
    <message>
        <source>&amp;Go to panel</source>
        <translation>&amp;Gehe zu Feld</translation>
    </message>
    <message>
        <source>Dispatch</source>
        <translation>Disposition</translation>
    </message>
    <message>
        <source>%1 and %2</source>
        <translation>%1 und %2</translation>
    </message>
    <message>
        <source>Stop failure</source>
        <translation>Stoppfehler</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Ausblenden</translation>
    </message>
    <message>
        <source>Hide this warning. It does not change what the machines do.</source>
        <translation>Diese Warnung ausblenden. Am Verhalten der Maschinen ändert das nichts.</translation>
    </message>
    <message>
        <source>&amp;Reset workspace</source>
        <translation>Arbeitsbereich &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Operator Control Unit %1
%2 on one console.</source>
        <translation>Bedienstation %1
%2 auf einer Konsole.</translation>
    </message>
    <message>
        <source>Stop every machine this console can reach</source>
        <translation>Alle Maschinen stoppen, die diese Konsole erreicht</translation>
    </message>
    <message>
        <source>Stop every machine this console can reach: %1</source>
        <translation>Alle Maschinen stoppen, die diese Konsole erreicht: %1</translation>
    </message>
    <message>
        <source>%1 (F12 or Ctrl+Shift+Space). Stopping never asks for confirmation; a stop that does not reach everything shows a red banner.</source>
        <translation>%1 (F12 oder Strg+Umschalt+Leertaste). Stoppen fragt nie nach Bestätigung; ein Stopp, der nicht alles erreicht, zeigt ein rotes Banner.</translation>
    </message>
    <message>
        <source>Workspaces (View › Reset workspace puts the current one back as it was):</source>
        <translation>Arbeitsbereiche (Ansicht › Arbeitsbereich zurücksetzen stellt den aktuellen wieder her):</translation>
    </message>
    <message>
        <source>%1 STOP ALL did NOT reach: %2</source>
        <translation>%1 ALLE STOPPEN hat NICHT erreicht: %2</translation>
    </message>
    <message>
        <source>%1 STOP did NOT reach: %2</source>
        <translation>%1 STOPP hat NICHT erreicht: %2</translation>
    </message>
    <message>
        <source>Production</source>
        <translation>Produktion</translation>
    </message>
    <message>
        <source>ISO 23725 all-stop to every AHS link</source>
        <translation>ISO 23725-Gesamtstopp an jede AHS-Verbindung</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Mission</translation>
    </message>
    <message>
        <source>Mission panel (Ctrl+U): Alt+E edit on the map, Alt+O open, Alt+I import GPX/KML, Alt+S save, Alt+L upload, Alt+P pause, Alt+B abort. Editing on the map: click adds a waypoint, drag moves it, click a leg inserts one; Insert or Enter adds at the cursor, Delete removes the selected one, Page Up/Down select, Shift+arrows move it, Ctrl+Z / Ctrl+Shift+Z undo / redo, Esc ends editing; right-click on the ground: Go here</source>
        <translation>Missionsfeld (Strg+U): Alt+B auf der Karte bearbeiten, Alt+F öffnen, Alt+I GPX/KML importieren, Alt+C speichern, Alt+H hochladen, Alt+P pausieren, Alt+A abbrechen. Bearbeiten in der Karte: Klick setzt einen Wegpunkt, Ziehen verschiebt ihn, Klick auf eine Teilstrecke fügt einen ein; Einfg oder Eingabe fügt an der Markierung ein, Entf löscht den ausgewählten, Bild auf/ab wählen aus, Umschalt+Pfeiltasten verschieben ihn, Strg+Z / Strg+Umschalt+Z rückgängig / wiederholen, Esc beendet das Bearbeiten; Rechtsklick auf den Boden: Hierher fahren</translation>
    </message>
    <message>
        <source>JAUS emergency stop to every discovered vehicle</source>
        <translation>JAUS-Not-Halt an jedes erkannte Fahrzeug</translation>
    </message>
    <message>
        <source>the OSYRIS stop message</source>
        <translation>die OSYRIS-Stoppmeldung</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>Video panel (Ctrl+I): camera, full screen (Esc returns), resume driving</source>
        <translation>Videofeld (Strg+I): Kamera, Vollbild (Esc kehrt zurück), Fahren fortsetzen</translation>
    </message>
    <message>
        <source>Control room</source>
        <translation>Leitstand</translation>
    </message>
</context>
<context>
    <name>ocu::MissionGeoJson</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>kein JSON (%1 bei Byte %2)</translation>
    </message>
    <message>
        <source>no GeoJSON LineString (the route) in it</source>
        <translation>kein GeoJSON-LineString (die Route) enthalten</translation>
    </message>
    <message>
        <source>the route has no positions</source>
        <translation>die Route hat keine Positionen</translation>
    </message>
    <message>
        <source>properties.waypoints must list one {speed, tolerance} per position (%1 positions)</source>
        <translation>properties.waypoints muss je Position ein {speed, tolerance} auflisten (%1 Positionen)</translation>
    </message>
    <message>
        <source>position %1 is not [longitude, latitude]</source>
        <translation>Position %1 ist nicht [Länge, Breite]</translation>
    </message>
    <message>
        <source>position %1 lies outside WGS84 (latitude %2, longitude %3)</source>
        <translation>Position %1 liegt außerhalb von WGS84 (Breite %2, Länge %3)</translation>
    </message>
    <message>
        <source>waypoint %1: speed must be a number of 0 or more, tolerance 0 to 100 m</source>
        <translation>Wegpunkt %1: Geschwindigkeit muss eine Zahl ab 0 sein, Toleranz 0 bis 100 m</translation>
    </message>
    <message>
        <source>cannot be opened (%1)</source>
        <translation>kann nicht geöffnet werden (%1)</translation>
    </message>
    <message>
        <source>too large for a mission file</source>
        <translation>zu groß für eine Missionsdatei</translation>
    </message>
    <message>
        <source>the plan has no waypoints to save</source>
        <translation>der Plan hat keine Wegpunkte zum Speichern</translation>
    </message>
    <message>
        <source>cannot be written (%1)</source>
        <translation>kann nicht geschrieben werden (%1)</translation>
    </message>
</context>
<context>
    <name>ocu::MissionImport</name>
    <message>
        <source>no such readable file</source>
        <translation>keine solche lesbare Datei</translation>
    </message>
    <message>
        <source>not a route GDAL can read (%1)</source>
        <translation>keine Route, die GDAL lesen kann (%1)</translation>
    </message>
    <message>
        <source>unknown format</source>
        <translation>unbekanntes Format</translation>
    </message>
    <message>
        <source>has no route, track or points</source>
        <translation>enthält keine Route, keinen Track und keine Punkte</translation>
    </message>
    <message>
        <source>has points outside WGS84</source>
        <translation>enthält Punkte außerhalb von WGS84</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPanel</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <source>1 waypoint</source>
        <translation>1 Wegpunkt</translation>
    </message>
    <message>
        <source>%1 waypoints</source>
        <translation>%1 Wegpunkte</translation>
    </message>
    <message>
        <source>Sending missions is not available in this build: the plan can be edited, saved, opened and drawn.</source>
        <translation>Missionen senden ist in diesem Build nicht verfügbar: der Plan kann bearbeitet, gespeichert, geöffnet und angezeigt werden.</translation>
    </message>
    <message>
        <source>&amp;Edit on map</source>
        <translation>Auf Karte &amp;bearbeiten</translation>
    </message>
    <message>
        <source>Click on the map to add waypoints, drag them, click a leg to insert one</source>
        <translation>In die Karte klicken, um Wegpunkte zu setzen, sie ziehen, auf eine Teilstrecke klicken, um einen einzufügen</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open a mission saved as GeoJSON</source>
        <translation>Eine als GeoJSON gespeicherte Mission öffnen</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importieren…</translation>
    </message>
    <message>
        <source>Import a route from GPX or KML</source>
        <translation>Eine Route aus GPX oder KML importieren</translation>
    </message>
    <message>
        <source>&amp;Save…</source>
        <translation>Spei&amp;chern…</translation>
    </message>
    <message>
        <source>Save the plan as GeoJSON</source>
        <translation>Den Plan als GeoJSON speichern</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Remove every waypoint (undo brings them back)</source>
        <translation>Alle Wegpunkte entfernen (Rückgängig holt sie zurück)</translation>
    </message>
    <message>
        <source>Delete waypoint</source>
        <translation>Wegpunkt löschen</translation>
    </message>
    <message>
        <source>Delete the selected waypoint (Delete)</source>
        <translation>Den ausgewählten Wegpunkt löschen (Entf)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Undo the last edit (Ctrl+Z)</source>
        <translation>Die letzte Änderung rückgängig machen (Strg+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Wiederholen (Strg+Umschalt+Z)</translation>
    </message>
    <message>
        <source>Up&amp;load</source>
        <translation>&amp;Hochladen</translation>
    </message>
    <message>
        <source>Send the plan to the vehicle; uploaded once read back equal</source>
        <translation>Den Plan an das Fahrzeug senden; hochgeladen, sobald er gleich zurückgelesen wurde</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Run the uploaded mission from the waypoint chosen beside</source>
        <translation>Die hochgeladene Mission ab dem daneben gewählten Wegpunkt ausführen</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Pause the running mission</source>
        <translation>Die laufende Mission anhalten</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Resume the paused mission</source>
        <translation>Die angehaltene Mission fortsetzen</translation>
    </message>
    <message>
        <source>A&amp;bort</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <source>Abort the mission</source>
        <translation>Die Mission abbrechen</translation>
    </message>
    <message>
        <source>from </source>
        <translation>ab </translation>
    </message>
    <message>
        <source>The waypoint the mission starts from</source>
        <translation>Der Wegpunkt, bei dem die Mission beginnt</translation>
    </message>
    <message>
        <source>Clear plan</source>
        <translation>Plan leeren</translation>
    </message>
    <message>
        <source>Sent to the command gate: the event log shows what went on the wire, the state above what the vehicle reports</source>
        <translation>An die Befehlsfreigabe gesendet: das Ereignisprotokoll zeigt, was gesendet wurde, der Zustand oben, was das Fahrzeug meldet</translation>
    </message>
    <message>
        <source>UGV %1</source>
        <translation>UGV %1</translation>
    </message>
    <message>
        <source>Mission of %1 (%2)</source>
        <translation>Mission von %1 (%2)</translation>
    </message>
    <message>
        <source>Select a UGV on the map or in the fleet list to plan its mission.</source>
        <translation>Ein UGV in der Karte oder der Flottenliste auswählen, um seine Mission zu planen.</translation>
    </message>
    <message>
        <source>%1: %2, %3</source>
        <translation>%1: %2, %3</translation>
    </message>
    <message>
        <source>No waypoints yet: Edit on map, then click on the map to add them.</source>
        <translation>Noch keine Wegpunkte: Auf Karte bearbeiten, dann in die Karte klicken, um sie zu setzen.</translation>
    </message>
    <message>
        <source>%1, %2, ETA %3</source>
        <translation>%1, %2, Ankunft %3</translation>
    </message>
    <message>
        <source>; from the vehicle %1, %2</source>
        <translation>; vom Fahrzeug %1, %2</translation>
    </message>
    <message>
        <source>Planned: %1, not uploaded</source>
        <translation>Geplant: %1, nicht hochgeladen</translation>
    </message>
    <message>
        <source>No mission</source>
        <translation>Keine Mission</translation>
    </message>
    <message>
        <source>Uploading %1…</source>
        <translation>Lade %1 hoch…</translation>
    </message>
    <message>
        <source>Uploaded and verified: %1</source>
        <translation>Hochgeladen und geprüft: %1</translation>
    </message>
    <message>
        <source>Running: waypoint %1 of %2</source>
        <translation>Läuft: Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>, %1 to go</source>
        <translation>, noch %1</translation>
    </message>
    <message>
        <source>, ETA %1</source>
        <translation>, Ankunft %1</translation>
    </message>
    <message>
        <source>Paused at waypoint %1 of %2</source>
        <translation>Angehalten bei Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>Completed: %1</source>
        <translation>Abgeschlossen: %1</translation>
    </message>
    <message>
        <source>Aborted at waypoint %1 of %2</source>
        <translation>Abgebrochen bei Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>Aborted</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>Stopped by emergency at waypoint %1 of %2</source>
        <translation>Durch Not-Halt gestoppt bei Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>Stopped by emergency</source>
        <translation>Durch Not-Halt gestoppt</translation>
    </message>
    <message>
        <source>; clearing the emergency does not restart it</source>
        <translation>; das Aufheben des Not-Halts startet sie nicht neu</translation>
    </message>
    <message>
        <source>Unknown, last seen at waypoint %1 of %2</source>
        <translation>Unbekannt, zuletzt gesehen bei Wegpunkt %1 von %2</translation>
    </message>
    <message>
        <source>Unknown: not seen running</source>
        <translation>Unbekannt: nicht laufend gesehen</translation>
    </message>
    <message>
        <source>Rejected: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <source>no reason given</source>
        <translation>kein Grund angegeben</translation>
    </message>
    <message>
        <source> (%1)</source>
        <translation> (%1)</translation>
    </message>
    <message>
        <source>; not ours: another console holds the vehicle&apos;s list driver</source>
        <translation>; nicht unsere: eine andere Konsole hält den List-Driver des Fahrzeugs</translation>
    </message>
    <message>
        <source>; the plan differs from the uploaded mission</source>
        <translation>; der Plan weicht von der hochgeladenen Mission ab</translation>
    </message>
    <message>
        <source>; driven path from the %1</source>
        <translation>; gefahrener Weg aus: %1</translation>
    </message>
    <message>
        <source>Go here sent to the command gate for %1: the event log shows what went on the wire</source>
        <translation>Hierher fahren für %1 an die Befehlsfreigabe gesendet: das Ereignisprotokoll zeigt, was gesendet wurde</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>%1 öffnen</translation>
    </message>
    <message>
        <source>Opened %1: %2</source>
        <translation>%1 geöffnet: %2</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Imported %1: %2 with the vehicle&apos;s default speed and tolerance</source>
        <translation>%1 importiert: %2 mit Standardgeschwindigkeit und -toleranz des Fahrzeugs</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Mission (*.geojson *.json)</source>
        <translation>Mission (*.geojson *.json)</translation>
    </message>
    <message>
        <source>Save mission</source>
        <translation>Mission speichern</translation>
    </message>
    <message>
        <source>Open mission</source>
        <translation>Mission öffnen</translation>
    </message>
    <message>
        <source>Import route</source>
        <translation>Route importieren</translation>
    </message>
    <message>
        <source>Routes (*.gpx *.kml);;All files (*)</source>
        <translation>Routen (*.gpx *.kml);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlan</name>
    <message>
        <source>Add waypoint %1</source>
        <translation>Wegpunkt %1 hinzufügen</translation>
    </message>
    <message>
        <source>Insert waypoint %1</source>
        <translation>Wegpunkt %1 einfügen</translation>
    </message>
    <message>
        <source>Move waypoint %1</source>
        <translation>Wegpunkt %1 verschieben</translation>
    </message>
    <message>
        <source>Delete waypoint %1</source>
        <translation>Wegpunkt %1 löschen</translation>
    </message>
    <message>
        <source>Speed of waypoint %1</source>
        <translation>Geschwindigkeit von Wegpunkt %1</translation>
    </message>
    <message>
        <source>Tolerance of waypoint %1</source>
        <translation>Toleranz von Wegpunkt %1</translation>
    </message>
    <message>
        <source>Default speeds and tolerances</source>
        <translation>Standardgeschwindigkeiten und -toleranzen</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlanEditor</name>
    <message>
        <source>Go here (%1)</source>
        <translation>Hierher fahren (%1)</translation>
    </message>
    <message>
        <source>Delete waypoint %1</source>
        <translation>Wegpunkt %1 löschen</translation>
    </message>
    <message>
        <source>Insert waypoint between %1 and %2</source>
        <translation>Wegpunkt zwischen %1 und %2 einfügen</translation>
    </message>
    <message>
        <source>Add waypoint here</source>
        <translation>Wegpunkt hier hinzufügen</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlanTableModel</name>
    <message>
        <source>vehicle</source>
        <translation>Fahrzeug</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Speed m/s</source>
        <translation>Geschw. m/s</translation>
    </message>
    <message>
        <source>Tolerance m</source>
        <translation>Toleranz m</translation>
    </message>
</context>
<context>
    <name>ocu::MissionTakeover</name>
    <message>
        <source>the mission was not paused: %1</source>
        <translation>die Mission wurde nicht angehalten: %1</translation>
    </message>
    <message>
        <source>a takeover of the mission is already being confirmed</source>
        <translation>eine Übernahme der Mission wird bereits bestätigt</translation>
    </message>
    <message>
        <source>Take over the mission?</source>
        <translation>Mission übernehmen?</translation>
    </message>
    <message>
        <source>%1 is running a mission (waypoint %2 of %3). Driving it by hand pauses the mission first; Resume in the mission panel continues it.</source>
        <translation>%1 fährt eine Mission (Wegpunkt %2 von %3). Manuelles Fahren hält die Mission zuerst an; „Fortsetzen“ im Missionsfeld setzt sie fort.</translation>
    </message>
    <message>
        <source>&amp;Pause and drive</source>
        <translation>&amp;Anhalten und fahren</translation>
    </message>
    <message>
        <source>&amp;Keep the mission</source>
        <translation>Mission &amp;behalten</translation>
    </message>
    <message>
        <source>no command gate</source>
        <translation>kein Befehls-Gate</translation>
    </message>
    <message>
        <source>the operator kept the mission</source>
        <translation>der Bediener hat die Mission behalten</translation>
    </message>
</context>
<context>
    <name>ocu::OperatorSession</name>
    <message>
        <source>idle for %1 s</source>
        <translation>%1 s untätig</translation>
    </message>
    <message>
        <source>no authentication</source>
        <translation>keine Authentifizierung</translation>
    </message>
    <message>
        <source>sign-in refused: %1</source>
        <translation>Anmeldung abgelehnt: %1</translation>
    </message>
    <message>
        <source>switch cancelled: control kept by %1</source>
        <translation>Wechsel abgebrochen: Steuerung bleibt bei %1</translation>
    </message>
    <message>
        <source>operator switched to %1</source>
        <translation>Bediener gewechselt zu %1</translation>
    </message>
    <message>
        <source>signed in as %1 after %2</source>
        <translation>als %1 angemeldet nach %2</translation>
    </message>
    <message>
        <source>on demand</source>
        <translation>auf Anforderung</translation>
    </message>
    <message>
        <source>console locked: %1</source>
        <translation>Konsole gesperrt: %1</translation>
    </message>
    <message>
        <source>unlock refused: %1</source>
        <translation>Entsperren abgelehnt: %1</translation>
    </message>
    <message>
        <source>console unlocked</source>
        <translation>Konsole entsperrt</translation>
    </message>
</context>
<context>
    <name>ocu::OperatorUi</name>
    <message>
        <source>S&amp;witch operator…</source>
        <translation>Bediener &amp;wechseln…</translation>
    </message>
    <message>
        <source>&amp;Lock</source>
        <translation>Konsole s&amp;perren</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Operator %1, role %2, at console %3 (File › Switch operator…)</source>
        <translation>Bediener %1, Rolle %2, an Konsole %3 (Datei › Bediener wechseln…)</translation>
    </message>
    <message>
        <source>Locked by %1 (%2)</source>
        <translation>Gesperrt von %1 (%2)</translation>
    </message>
    <message>
        <source>Switch operator</source>
        <translation>Bediener wechseln</translation>
    </message>
    <message>
        <source>The next operator signs in with their own password. The machines keep running.</source>
        <translation>Der nächste Bediener meldet sich mit seinem eigenen Passwort an. Die Maschinen laufen weiter.</translation>
    </message>
    <message>
        <source>no operator session</source>
        <translation>keine Bedienersitzung</translation>
    </message>
    <message>
        <source>Release control</source>
        <translation>Steuerung freigeben</translation>
    </message>
    <message>
        <source>The new operator&apos;s role may not control machines. Release control of %1?</source>
        <translation>Die Rolle des neuen Bedieners darf keine Maschinen steuern. Steuerung von %1 freigeben?</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Entsperren</translation>
    </message>
    <message>
        <source>Enter your password to unlock the console.</source>
        <translation>Geben Sie Ihr Passwort ein, um die Konsole zu entsperren.</translation>
    </message>
</context>
<context>
    <name>ocu::OsyrisBridge</name>
    <message>
        <source>OSYRIS: %1</source>
        <translation>OSYRIS: %1</translation>
    </message>
    <message>
        <source>joined, waiting for stations</source>
        <translation>beigetreten, warte auf Stationen</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Maschine %1</translation>
    </message>
    <message>
        <source>vibration on</source>
        <translation>Vibration ein</translation>
    </message>
    <message>
        <source>vibration off</source>
        <translation>Vibration aus</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>rückwärts</translation>
    </message>
    <message>
        <source>standing</source>
        <translation>steht</translation>
    </message>
    <message>
        <source>GPS shadow</source>
        <translation>GPS-Abschattung</translation>
    </message>
    <message>
        <source>position not valid</source>
        <translation>Position ungültig</translation>
    </message>
    <message>
        <source>low position accuracy</source>
        <translation>geringe Positionsgenauigkeit</translation>
    </message>
    <message>
        <source>high accuracy</source>
        <translation>hohe Genauigkeit</translation>
    </message>
    <message>
        <source>medium accuracy</source>
        <translation>mittlere Genauigkeit</translation>
    </message>
    <message>
        <source>stations heard</source>
        <translation>Stationen empfangen</translation>
    </message>
    <message>
        <source>ping: &quot;idx&quot; must be a station index 0-253</source>
        <translation>ping: &quot;idx&quot; muss ein Stationsindex 0-253 sein</translation>
    </message>
    <message>
        <source>send_text: &quot;%1&quot; is not an OSYRIS station</source>
        <translation>send_text: „%1“ ist keine OSYRIS-Station</translation>
    </message>
    <message>
        <source>send_text: &quot;text&quot; must be 1 to 79 bytes (CmMsg)</source>
        <translation>send_text: „text“ muss 1 bis 79 Bytes lang sein (CmMsg)</translation>
    </message>
    <message>
        <source>Message from %1 (%2): %3</source>
        <translation>Nachricht von %1 (%2): %3</translation>
    </message>
    <message>
        <source>station %1</source>
        <translation>Station %1</translation>
    </message>
    <message>
        <source>%1: %2 positions given up as unobtainable (slots %3); their cells are marked incomplete</source>
        <translation>%1: %2 Positionen als nicht erhältlich aufgegeben (Slots %3); ihre Zellen sind als unvollständig markiert</translation>
    </message>
    <message>
        <source>OSYRIS station stopped</source>
        <translation>OSYRIS-Station gestoppt</translation>
    </message>
    <message>
        <source>implausible position ignored (slot %1): %2</source>
        <translation>unplausible Position verworfen (Slot %1): %2</translation>
    </message>
    <message>
        <source>%1 refused: the OSYRIS station is not running; nothing sent</source>
        <translation>%1 abgelehnt: die OSYRIS-Station läuft nicht; nichts gesendet</translation>
    </message>
    <message>
        <source>%1 refused: no OSYRIS station heard on %2:%3 yet; nothing sent</source>
        <translation>%1 abgelehnt: auf %2:%3 wurde noch keine OSYRIS-Station empfangen; nichts gesendet</translation>
    </message>
    <message>
        <source>STOP message</source>
        <translation>STOP-Meldung</translation>
    </message>
    <message>
        <source>not an OSYRIS machine</source>
        <translation>keine OSYRIS-Maschine</translation>
    </message>
    <message>
        <source>OSYRIS machines carry no stop state to clear</source>
        <translation>OSYRIS-Maschinen haben keinen Stoppzustand zum Aufheben</translation>
    </message>
    <message>
        <source>no station heard for %1 s</source>
        <translation>seit %1 s keine Station gehört</translation>
    </message>
</context>
<context>
    <name>ocu::OwnPosition</name>
    <message>
        <source>position source error %1</source>
        <translation>Fehler der Positionsquelle %1</translation>
    </message>
    <message>
        <source>no system position source available</source>
        <translation>keine System-Positionsquelle verfügbar</translation>
    </message>
    <message>
        <source>cannot open NMEA log %1: %2</source>
        <translation>NMEA-Log %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>no NMEA device</source>
        <translation>kein NMEA-Gerät</translation>
    </message>
</context>
<context>
    <name>ocu::PanTiltController</name>
    <message>
        <source>camera control disabled</source>
        <translation>Kamerasteuerung deaktiviert</translation>
    </message>
    <message>
        <source>hat released</source>
        <translation>Coolie-Hat losgelassen</translation>
    </message>
    <message>
        <source>joystick unplugged</source>
        <translation>Joystick abgezogen</translation>
    </message>
    <message>
        <source>keys released</source>
        <translation>Tasten losgelassen</translation>
    </message>
    <message>
        <source>stick released</source>
        <translation>Stick losgelassen</translation>
    </message>
    <message>
        <source>input released</source>
        <translation>Eingabe losgelassen</translation>
    </message>
</context>
<context>
    <name>ocu::PassCountPanel</name>
    <message>
        <source>Pass count (discrete)</source>
        <translation>Überfahrten (diskret)</translation>
    </message>
    <message>
        <source>Summary (below / within / above)</source>
        <translation>Übersicht (unter / im / über Soll)</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <source>Target passes</source>
        <translation>Soll-Überfahrten</translation>
    </message>
    <message>
        <source>No pass-count data</source>
        <translation>Keine Überfahrtsdaten</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%1&apos;&gt;■&lt;/span&gt; below %2&lt;/td&gt;&lt;td align=right&gt;%3 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%4&apos;&gt;■&lt;/span&gt; within %5–%6&lt;/td&gt;&lt;td align=right&gt;%7 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%8&apos;&gt;■&lt;/span&gt; above %6&lt;/td&gt;&lt;td align=right&gt;%9 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;covered area&lt;/td&gt;&lt;td align=right&gt;%10 m²&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%1&apos;&gt;■&lt;/span&gt; unter %2&lt;/td&gt;&lt;td align=right&gt;%3 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%4&apos;&gt;■&lt;/span&gt; im Soll %5–%6&lt;/td&gt;&lt;td align=right&gt;%7 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%8&apos;&gt;■&lt;/span&gt; über %6&lt;/td&gt;&lt;td align=right&gt;%9 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;abgedeckte Fläche&lt;/td&gt;&lt;td align=right&gt;%10 m²&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Überfahrten</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Lift</source>
        <translation>Lage</translation>
    </message>
    <message>
        <source>Filters</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>Vibrating only</source>
        <translation>Nur mit Vibration</translation>
    </message>
    <message>
        <source>Static only</source>
        <translation>Nur statisch</translation>
    </message>
    <message>
        <source>Vibrating and static</source>
        <translation>Vibration und statisch</translation>
    </message>
    <message>
        <source>Both directions</source>
        <translation>Beide Richtungen</translation>
    </message>
    <message>
        <source>Forward only</source>
        <translation>Nur vorwärts</translation>
    </message>
    <message>
        <source>Backward only</source>
        <translation>Nur rückwärts</translation>
    </message>
    <message>
        <source> km/h</source>
        <translation> km/h</translation>
    </message>
    <message>
        <source>any</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>Time window</source>
        <translation>Zeitfenster</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>one lift</source>
        <translation>eine Lage</translation>
    </message>
    <message>
        <source>Lifts are elevation bands of this thickness in the machines&apos; heights</source>
        <translation>Lagen sind Höhenbänder dieser Dicke in den Höhen der Maschinen</translation>
    </message>
    <message>
        <source>Vibration</source>
        <translation>Vibration</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Lift thickness</source>
        <translation>Lagendicke</translation>
    </message>
    <message>
        <source>Top-most lift</source>
        <translation>Oberste Lage</translation>
    </message>
    <message>
        <source>Lift %1 (z %2 – %3 m)</source>
        <translation>Lage %1 (z %2 – %3 m)</translation>
    </message>
</context>
<context>
    <name>ocu::PlatformServicesWidget</name>
    <message>
        <source>Set mode</source>
        <translation>Modus setzen</translation>
    </message>
    <message>
        <source>Set state…</source>
        <translation>Zustand setzen…</translation>
    </message>
    <message>
        <source>Emergency state</source>
        <translation>Notzustand</translation>
    </message>
    <message>
        <source>Reset trip</source>
        <translation>Tagesstrecke nullen</translation>
    </message>
    <message>
        <source>Platform state</source>
        <translation>Plattformzustand</translation>
    </message>
    <message>
        <source>Put the whole platform in its emergency state: every component halts and refuses commands until it is set back to operational (AEP-4818 §6.2.6)</source>
        <translation>Die gesamte Plattform in den Notzustand setzen: jede Komponente hält an und verweigert Befehle, bis sie wieder auf betriebsbereit gesetzt wird (AEP-4818 §6.2.6)</translation>
    </message>
    <message>
        <source>Platform mode:</source>
        <translation>Plattformmodus:</translation>
    </message>
    <message>
        <source>Platform state:</source>
        <translation>Plattformzustand:</translation>
    </message>
    <message>
        <source>Odometer:</source>
        <translation>Wegstrecke:</translation>
    </message>
    <message>
        <source>Put %1 in the platform state &quot;%2&quot;?</source>
        <translation>%1 in den Plattformzustand „%2“ setzen?</translation>
    </message>
    <message>
        <source>not offered</source>
        <translation>nicht angeboten</translation>
    </message>
    <message>
        <source>not reported yet</source>
        <translation>noch nicht gemeldet</translation>
    </message>
    <message>
        <source> (last request refused: %1)</source>
        <translation> (letzte Anfrage abgelehnt: %1)</translation>
    </message>
    <message>
        <source>%1 · trip %2</source>
        <translation>%1 · Tagesstrecke %2</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Comms-lost policy: offered (%1 %2); setting a policy waits for a published message layout</source>
        <translation>Verhalten bei Verbindungsverlust: angeboten (%1 %2); das Setzen wartet auf ein veröffentlichtes Nachrichtenformat</translation>
    </message>
    <message>
        <source>Comms-lost policy: not offered by this vehicle</source>
        <translation>Verhalten bei Verbindungsverlust: von diesem Fahrzeug nicht angeboten</translation>
    </message>
</context>
<context>
    <name>ocu::ProductionModel</name>
    <message>
        <source>Shift</source>
        <translation>Schicht</translation>
    </message>
    <message>
        <source>unknown shovel</source>
        <translation>unbekannter Bagger</translation>
    </message>
    <message>
        <source>unknown dump</source>
        <translation>unbekannte Kippe</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>Weg %1</translation>
    </message>
</context>
<context>
    <name>ocu::ProductionView</name>
    <message>
        <source>Plan (t/shift):</source>
        <translation>Plan (t/Schicht):</translation>
    </message>
    <message>
        <source>Tonnes planned for the shift (0: no plan)</source>
        <translation>Für die Schicht geplante Tonnen (0: kein Plan)</translation>
    </message>
    <message>
        <source>Shift &amp;report…</source>
        <translation>Schicht&amp;bericht…</translation>
    </message>
    <message>
        <source>Write the shift report as PDF and CSV</source>
        <translation>Den Schichtbericht als PDF und CSV schreiben</translation>
    </message>
    <message>
        <source>New shift</source>
        <translation>Neue Schicht</translation>
    </message>
    <message>
        <source>Start counting a new shift now (the current figures are discarded)</source>
        <translation>Jetzt eine neue Schicht zu zählen beginnen (die aktuellen Zahlen werden verworfen)</translation>
    </message>
    <message>
        <source>Start a new shift now? The current shift&apos;s figures are discarded; write the shift report first.</source>
        <translation>Jetzt eine neue Schicht beginnen? Die Zahlen der aktuellen Schicht werden verworfen; schreiben Sie zuerst den Schichtbericht.</translation>
    </message>
    <message>
        <source>Trucks</source>
        <translation>Lkw</translation>
    </message>
    <message>
        <source>Shovels</source>
        <translation>Bagger</translation>
    </message>
    <message>
        <source>Dumps</source>
        <translation>Kippen</translation>
    </message>
    <message>
        <source>Truck</source>
        <translation>Lkw</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>Ladungen</translation>
    </message>
    <message>
        <source>Tonnes</source>
        <translation>Tonnen</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Umläufe</translation>
    </message>
    <message>
        <source>Queue</source>
        <translation>Warten</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Ansetzen</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Laden</translation>
    </message>
    <message>
        <source>Haul</source>
        <translation>Transport</translation>
    </message>
    <message>
        <source>Dump</source>
        <translation>Kippen</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>Rückfahrt</translation>
    </message>
    <message>
        <source>Cycle parts: average minutes:seconds per cycle</source>
        <translation>Umlaufteile: Mittelwert Minuten:Sekunden je Umlauf</translation>
    </message>
    <message>
        <source>%1 % of the %2 t due by now</source>
        <translation>%1 % der bis jetzt fälligen %2 t</translation>
    </message>
    <message>
        <source>no plan set</source>
        <translation>kein Plan gesetzt</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 t&lt;/b&gt; in &lt;b&gt;%2 loads&lt;/b&gt; · %3 cycles, average %4 · %5</source>
        <translation>&lt;b&gt;%1 t&lt;/b&gt; in &lt;b&gt;%2 Ladungen&lt;/b&gt; · %3 Umläufe, Mittelwert %4 · %5</translation>
    </message>
    <message>
        <source>Shift report</source>
        <translation>Schichtbericht</translation>
    </message>
    <message>
        <source>Written:
%1
%2</source>
        <translation>Geschrieben:
%1
%2</translation>
    </message>
    <message>
        <source>The shift report was not written: %1</source>
        <translation>Der Schichtbericht wurde nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
</context>
<context>
    <name>ocu::ReplayTimeline</name>
    <message>
        <source>Step back (Left)</source>
        <translation>Schritt zurück (Links)</translation>
    </message>
    <message>
        <source>Play backwards</source>
        <translation>Rückwärts abspielen</translation>
    </message>
    <message>
        <source>Play / pause (Space)</source>
        <translation>Abspielen / Pause (Leertaste)</translation>
    </message>
    <message>
        <source>Step forward (Right)</source>
        <translation>Schritt vor (Rechts)</translation>
    </message>
    <message>
        <source>Speed (+ / -)</source>
        <translation>Geschwindigkeit (+ / -)</translation>
    </message>
    <message>
        <source>HH:MM:SS or seconds</source>
        <translation>HH:MM:SS oder Sekunden</translation>
    </message>
    <message>
        <source>Go to an exact time: HH:MM:SS[.mmm] (UTC), seconds after the start, or ISO 8601; Enter</source>
        <translation>Zu einer genauen Zeit springen: HH:MM:SS[.mmm] (UTC), Sekunden nach dem Start oder ISO 8601; Eingabe</translation>
    </message>
    <message>
        <source>Not a time: %1</source>
        <translation>Keine Zeitangabe: %1</translation>
    </message>
</context>
<context>
    <name>ocu::SdlJoystickInput</name>
    <message>
        <source>No joystick</source>
        <translation>Kein Joystick</translation>
    </message>
</context>
<context>
    <name>ocu::SignInDialog</name>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Benutzer:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>&amp;Sign in</source>
        <translation>&amp;Anmelden</translation>
    </message>
    <message>
        <source>no check</source>
        <translation>keine Prüfung</translation>
    </message>
</context>
<context>
    <name>ocu::Site3DFeed</name>
    <message>
        <source>below %1</source>
        <translation>unter %1</translation>
    </message>
    <message>
        <source>%1–%2</source>
        <translation>%1–%2</translation>
    </message>
    <message>
        <source>above %1</source>
        <translation>über %1</translation>
    </message>
</context>
<context>
    <name>ocu::Site3DView</name>
    <message>
        <source>Orbit</source>
        <translation>Orbit</translation>
    </message>
    <message>
        <source>Free orbit camera (drag to rotate, wheel to zoom)</source>
        <translation>Freie Orbit-Kamera (Ziehen zum Drehen, Mausrad zum Zoomen)</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Folgen</translation>
    </message>
    <message>
        <source>Keep the selected machine in the centre</source>
        <translation>Ausgewählte Maschine in der Mitte halten</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <source>Top-down view, north up</source>
        <translation>Draufsicht, Norden oben</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Ansicht zurücksetzen</translation>
    </message>
    <message>
        <source>3D view unavailable: %1</source>
        <translation>3D-Ansicht nicht verfügbar: %1</translation>
    </message>
</context>
<context>
    <name>ocu::SiteMapView</name>
    <message>
        <source>below (&lt;%1)</source>
        <translation>unter (&lt;%1)</translation>
    </message>
    <message>
        <source>within %1–%2</source>
        <translation>im Soll %1–%2</translation>
    </message>
    <message>
        <source>above (&gt;%1)</source>
        <translation>über (&gt;%1)</translation>
    </message>
    <message>
        <source>Passes · target %1–%2</source>
        <translation>Überfahrten · Soll %1–%2</translation>
    </message>
    <message>
        <source>type unknown</source>
        <translation>Typ unbekannt</translation>
    </message>
    <message>
        <source>Status: %1</source>
        <translation>Status: %1</translation>
    </message>
    <message>
        <source>Mode: %1</source>
        <translation>Modus: %1</translation>
    </message>
    <message>
        <source>Speed: %1 km/h · heading %2°</source>
        <translation>Geschw.: %1 km/h · Kurs %2°</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Gestoppt: %1</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>Health: %1</source>
        <translation>Zustand: %1</translation>
    </message>
    <message>
        <source>Control: %1</source>
        <translation>Steuerung: %1</translation>
    </message>
    <message>
        <source>Link: %1 · data %2 s ago</source>
        <translation>Verbindung: %1 · Daten vor %2 s</translation>
    </message>
</context>
<context>
    <name>ocu::SiteRuntime</name>
    <message>
        <source>Simulated site: %1</source>
        <translation>Simulierte Baustelle: %1</translation>
    </message>
    <message>
        <source>Own position: %1</source>
        <translation>Eigene Position: %1</translation>
    </message>
    <message>
        <source>This build has no 3D view (configured with OCU_WITH_VTK=OFF).</source>
        <translation>Dieser Build hat keine 3D-Ansicht (konfiguriert mit OCU_WITH_VTK=OFF).</translation>
    </message>
    <message>
        <source>3D terrain not shown: %1</source>
        <translation>3D-Gelände nicht angezeigt: %1</translation>
    </message>
    <message>
        <source>Crew messages</source>
        <translation>Nachrichten an die Mannschaft</translation>
    </message>
    <message>
        <source>Crew messages (%1)</source>
        <translation>Nachrichten an die Mannschaft (%1)</translation>
    </message>
    <message>
        <source>console started</source>
        <translation>Konsole gestartet</translation>
    </message>
    <message>
        <source>control-room history connected</source>
        <translation>Leitstand-Historie verbunden</translation>
    </message>
    <message>
        <source>control-room history unavailable (kept locally, back-filled on return): %1</source>
        <translation>Leitstand-Historie nicht verfügbar (lokal gespeichert, bei Rückkehr nachgetragen): %1</translation>
    </message>
    <message>
        <source>Control-room history: %1</source>
        <translation>Leitstand-Historie: %1</translation>
    </message>
    <message>
        <source>Flight recorder: %1</source>
        <translation>Flugschreiber: %1</translation>
    </message>
    <message>
        <source>Recording this run to %1</source>
        <translation>Dieser Lauf wird aufgezeichnet nach %1</translation>
    </message>
    <message>
        <source>Map background not shown: %1</source>
        <translation>Kartenhintergrund nicht angezeigt: %1</translation>
    </message>
    <message>
        <source>STOP button ready</source>
        <translation>STOP-Taster bereit</translation>
    </message>
    <message>
        <source>STOP button not connected</source>
        <translation>STOP-Taster nicht verbunden</translation>
    </message>
    <message>
        <source>%1: %2 triggers STOP ALL</source>
        <translation>%1: %2 löst ALLE STOPPEN aus</translation>
    </message>
    <message>
        <source>No device with %1 is connected; STOP ALL stays on F12, Ctrl+Shift+Space and the toolbar</source>
        <translation>Kein Gerät mit %1 verbunden; ALLE STOPPEN bleibt auf F12, Strg+Umschalt+Leertaste und der Werkzeugleiste</translation>
    </message>
    <message>
        <source>Areas and reports</source>
        <translation>Flächen und Berichte</translation>
    </message>
    <message>
        <source>console closed</source>
        <translation>Konsole geschlossen</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopController</name>
    <message>
        <source>control lost or disabled</source>
        <translation>Steuerung verloren oder deaktiviert</translation>
    </message>
    <message>
        <source>joystick released</source>
        <translation>Joystick losgelassen</translation>
    </message>
    <message>
        <source>joystick unplugged</source>
        <translation>Joystick abgesteckt</translation>
    </message>
    <message>
        <source>dead-man key released</source>
        <translation>Totmanntaste losgelassen</translation>
    </message>
    <message>
        <source>keys released</source>
        <translation>Tasten losgelassen</translation>
    </message>
    <message>
        <source>stick released</source>
        <translation>Stick losgelassen</translation>
    </message>
    <message>
        <source>input released</source>
        <translation>Eingabe losgelassen</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopPanel</name>
    <message>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <source>Hold to clear emergency</source>
        <translation>Halten, um Not-Halt aufzuheben</translation>
    </message>
    <message>
        <source>Emergency stop of this vehicle (Space or Esc). Never asks for confirmation.</source>
        <translation>Not-Halt dieses Fahrzeugs (Leertaste oder Esc). Fragt nie nach Bestätigung.</translation>
    </message>
    <message>
        <source>Velocity (m/s, rad/s)</source>
        <translation>Geschwindigkeit (m/s, rad/s)</translation>
    </message>
    <message>
        <source>Wrench effort (%)</source>
        <translation>Stellwert (%)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Geschwindigkeitsbegrenzung</translation>
    </message>
    <message>
        <source>Joystick</source>
        <translation>Joystick</translation>
    </message>
    <message>
        <source>window lost focus</source>
        <translation>Fenster hat Fokus verloren</translation>
    </message>
    <message>
        <source>vehicle changed</source>
        <translation>Fahrzeug gewechselt</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>none connected</source>
        <translation>keines angeschlossen</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keines</translation>
    </message>
    <message>
        <source>No JAUS vehicle selected</source>
        <translation>Kein JAUS-Fahrzeug ausgewählt</translation>
    </message>
    <message>
        <source>Select a vehicle in the fleet list or the JAUS control panel, then take control.</source>
        <translation>Fahrzeug in der Flottenliste oder im JAUS-Steuerungspanel auswählen, dann Steuerung übernehmen.</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>MONITOR role: driving disabled</source>
        <translation>Rolle MONITOR: Fahren deaktiviert</translation>
    </message>
    <message>
        <source>not controlled by this console: take control first</source>
        <translation>nicht von dieser Konsole gesteuert: zuerst Steuerung übernehmen</translation>
    </message>
    <message>
        <source>controlled by this console</source>
        <translation>von dieser Konsole gesteuert</translation>
    </message>
    <message>
        <source>EMERGENCY — hold the clear button to release</source>
        <translation>EMERGENCY — zum Aufheben die Freigabetaste halten</translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>Verbindung %1</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>Zustand %1</translation>
    </message>
    <message>
        <source>drive session open</source>
        <translation>Fahrsitzung offen</translation>
    </message>
    <message>
        <source>drive session closed (vehicle stops after its 1 s drive timeout)</source>
        <translation>Fahrsitzung geschlossen (Fahrzeug hält nach seinem Fahr-Timeout von 1 s an)</translation>
    </message>
    <message>
        <source>speed %1 m/s</source>
        <translation>Geschw. %1 m/s</translation>
    </message>
    <message>
        <source>heading %1°</source>
        <translation>Kurs %1°</translation>
    </message>
    <message>
        <source>pose %1, %2</source>
        <translation>Pose %1, %2</translation>
    </message>
    <message>
        <source>local %1 / %2 m</source>
        <translation>lokal %1 / %2 m</translation>
    </message>
    <message>
        <source>%1 % · %2 m/s</source>
        <translation>%1 % · %2 m/s</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>teleop panel lost keyboard focus</source>
        <translation>Fernsteuerungs-Panel hat Tastaturfokus verloren</translation>
    </message>
    <message>
        <source>teleop panel hidden</source>
        <translation>Fernsteuerungs-Panel ausgeblendet</translation>
    </message>
    <message>
        <source>Mapping…</source>
        <translation>Belegung…</translation>
    </message>
    <message>
        <source>Choose the joystick axes, their direction and the dead zone</source>
        <translation>Joystick-Achsen, ihre Richtung und die Totzone wählen</translation>
    </message>
    <message>
        <source>joystick mapping</source>
        <translation>Joystick-Belegung</translation>
    </message>
    <message>
        <source>Stick: camera</source>
        <translation>Stick: Kamera</translation>
    </message>
    <message>
        <source>The on-screen stick pans and tilts the camera instead of driving</source>
        <translation>Der Bildschirm-Stick schwenkt und neigt die Kamera, statt zu fahren</translation>
    </message>
    <message>
        <source>Keyboard: hold Shift (dead-man) and use W/A/S/D or the arrows. Camera: J/L pan, I/K tilt (or the joystick hat).</source>
        <translation>Tastatur: Umschalt (Totmann) halten und W/A/S/D oder die Pfeiltasten benutzen. Kamera: J/L schwenken, I/K neigen (oder Coolie-Hat des Joysticks).</translation>
    </message>
    <message>
        <source>camera changed</source>
        <translation>Kamera gewechselt</translation>
    </message>
    <message>
        <source>Camera pan-tilt refused: %1</source>
        <translation>Schwenken/Neigen der Kamera abgelehnt: %1</translation>
    </message>
    <message>
        <source>EMERGENCY</source>
        <translation>NOTHALT</translation>
    </message>
    <message>
        <source>driving held (video)</source>
        <translation>Fahren angehalten (Video)</translation>
    </message>
    <message>
        <source>ready to drive</source>
        <translation>fahrbereit</translation>
    </message>
    <message>
        <source>not driving</source>
        <translation>fährt nicht</translation>
    </message>
    <message>
        <source>video window closed or lost focus</source>
        <translation>Videofenster geschlossen oder Fokus verloren</translation>
    </message>
    <message>
        <source>teleop panel closed</source>
        <translation>Fernsteuerungsfeld geschlossen</translation>
    </message>
    <message>
        <source>no command gate: driving is not possible</source>
        <translation>keine Befehlsfreigabe: Fahren nicht möglich</translation>
    </message>
    <message>
        <source>teleop input</source>
        <translation>Fernsteuerungseingabe</translation>
    </message>
    <message>
        <source>Drive session NOT started: %1</source>
        <translation>Fahrsitzung NICHT gestartet: %1</translation>
    </message>
    <message>
        <source>Drive session end: zero commands NOT sent: %1</source>
        <translation>Ende der Fahrsitzung: Null-Befehle NICHT gesendet: %1</translation>
    </message>
    <message>
        <source>Driving stopped: %1</source>
        <translation>Fahren gestoppt: %1</translation>
    </message>
    <message>
        <source>the link to %1 is %2</source>
        <translation>die Verbindung zu %1 ist %2</translation>
    </message>
    <message>
        <source>%1 is in EMERGENCY</source>
        <translation>%1 ist im NOT-HALT</translation>
    </message>
    <message>
        <source>this console no longer controls %1</source>
        <translation>diese Konsole steuert %1 nicht mehr</translation>
    </message>
    <message>
        <source>driving is not allowed</source>
        <translation>Fahren ist nicht erlaubt</translation>
    </message>
    <message>
        <source>teleop video hidden</source>
        <translation>Fernsteuerungsvideo ausgeblendet</translation>
    </message>
    <message>
        <source>The vehicle runs a mission: confirm to pause it before driving</source>
        <translation>Das Fahrzeug fährt eine Mission: zum Fahren erst deren Anhalten bestätigen</translation>
    </message>
    <message>
        <source>Mission paused: driving by hand (Resume in the mission panel)</source>
        <translation>Mission angehalten: manuelles Fahren (Fortsetzen im Missionsfeld)</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopVideoPane</name>
    <message>
        <source>Teleoperation video</source>
        <translation>Teleoperations-Video</translation>
    </message>
    <message>
        <source>Full screen</source>
        <translation>Vollbild</translation>
    </message>
    <message>
        <source>Resume driving</source>
        <translation>Fahren fortsetzen</translation>
    </message>
    <message>
        <source>No camera on this vehicle</source>
        <translation>Keine Kamera an diesem Fahrzeug</translation>
    </message>
    <message>
        <source>Camera shown (announced by the vehicle or configured for it)</source>
        <translation>Angezeigte Kamera (vom Fahrzeug angekündigt oder für es konfiguriert)</translation>
    </message>
    <message>
        <source>Show the video full screen (Esc returns); driving keys keep working there</source>
        <translation>Video im Vollbild zeigen (Esc kehrt zurück); die Fahrtasten wirken dort weiter</translation>
    </message>
    <message>
        <source>The video watchdog stopped driving: resume once the video is back</source>
        <translation>Der Video-Watchdog hat das Fahren gestoppt: fortsetzen, sobald das Video zurück ist</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>camera %1</source>
        <translation>Kamera %1</translation>
    </message>
    <message>
        <source> (configured)</source>
        <translation> (konfiguriert)</translation>
    </message>
    <message>
        <source>%1 — pan-tilt: J/L/I/K, the stick&apos;s camera mode or the joystick hat</source>
        <translation>%1 — Schwenken/Neigen: J/L/I/K, Kameramodus des Sticks oder Coolie-Hat des Joysticks</translation>
    </message>
    <message>
        <source>no camera</source>
        <translation>keine Kamera</translation>
    </message>
</context>
<context>
    <name>ocu::TimelineMarkerStrip</name>
    <message>
        <source>command: </source>
        <translation>Befehl: </translation>
    </message>
    <message>
        <source>alarm: </source>
        <translation>Alarm: </translation>
    </message>
</context>
<context>
    <name>ocu::VehicleDetailsWidget</name>
    <message>
        <source>Item</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Identification</source>
        <translation>Identifikation</translation>
    </message>
    <message>
        <source>Call sign</source>
        <translation>Rufzeichen</translation>
    </message>
    <message>
        <source>Subsystem ID</source>
        <translation>Subsystem-ID</translation>
    </message>
    <message>
        <source>Endpoint</source>
        <translation>Endpunkt</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>Management</source>
        <translation>Verwaltung</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Emergency</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>YES</source>
        <translation>JA</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Drive session</source>
        <translation>Fahrsitzung</translation>
    </message>
    <message>
        <source>open</source>
        <translation>offen</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>geschlossen</translation>
    </message>
    <message>
        <source>Access timeout</source>
        <translation>Zugriffs-Timeout</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Platform</source>
        <translation>Plattform</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Steering</source>
        <translation>Lenkung</translation>
    </message>
    <message>
        <source>Ackermann</source>
        <translation>Ackermann</translation>
    </message>
    <message>
        <source>skid steer</source>
        <translation>Skid-Steer</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Max forward speed</source>
        <translation>Max. Vorwärtsgeschwindigkeit</translation>
    </message>
    <message>
        <source>Max reverse speed</source>
        <translation>Max. Rückwärtsgeschwindigkeit</translation>
    </message>
    <message>
        <source>Max rotational speed</source>
        <translation>Max. Drehgeschwindigkeit</translation>
    </message>
    <message>
        <source>Specifications</source>
        <translation>Spezifikationen</translation>
    </message>
    <message>
        <source>not reported yet</source>
        <translation>noch nicht gemeldet</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Pose</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Breitengrad</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Längengrad</translation>
    </message>
    <message>
        <source>Altitude</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Kurs</translation>
    </message>
    <message>
        <source>Local X</source>
        <translation>Lokal X</translation>
    </message>
    <message>
        <source>Local Y</source>
        <translation>Lokal Y</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Yaw rate</source>
        <translation>Gierrate</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>Services</source>
        <translation>Dienste</translation>
    </message>
    <message>
        <source>Subsystem %1</source>
        <translation>Subsystem %1</translation>
    </message>
    <message>
        <source>Platform services</source>
        <translation>Plattformdienste</translation>
    </message>
    <message>
        <source>not offered</source>
        <translation>nicht angeboten</translation>
    </message>
    <message>
        <source>Platform mode</source>
        <translation>Plattformmodus</translation>
    </message>
    <message>
        <source>Platform state</source>
        <translation>Plattformzustand</translation>
    </message>
    <message>
        <source>Lights</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>all off</source>
        <translation>alle aus</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Odometer</source>
        <translation>Wegstrecke</translation>
    </message>
    <message>
        <source>Trip</source>
        <translation>Tagesstrecke</translation>
    </message>
    <message>
        <source>Comms-lost policy service</source>
        <translation>Dienst für Verhalten bei Verbindungsverlust</translation>
    </message>
</context>
<context>
    <name>ocu::VideoPlayer</name>
    <message>
        <source>no video</source>
        <translation>kein Video</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbinde</translation>
    </message>
    <message>
        <source>playing</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>video LOST</source>
        <translation>Video VERLOREN</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>verbinde neu</translation>
    </message>
    <message>
        <source>no video URL</source>
        <translation>keine Video-URL</translation>
    </message>
    <message>
        <source>not an RTSP URL: %1</source>
        <translation>keine RTSP-URL: %1</translation>
    </message>
    <message>
        <source>GStreamer elements missing</source>
        <translation>GStreamer-Elemente fehlen</translation>
    </message>
    <message>
        <source>cannot link the video pipeline</source>
        <translation>die Video-Pipeline lässt sich nicht verbinden</translation>
    </message>
    <message>
        <source>the video pipeline did not start</source>
        <translation>die Video-Pipeline ist nicht gestartet</translation>
    </message>
    <message>
        <source>no video from %1</source>
        <translation>kein Video von %1</translation>
    </message>
    <message>
        <source>no frame for %1 ms</source>
        <translation>seit %1 ms kein Bild</translation>
    </message>
</context>
<context>
    <name>ocu::VideoView</name>
    <message>
        <source>%1 fps</source>
        <translation>%1 fps</translation>
    </message>
    <message>
        <source>frame age %1 ms</source>
        <translation>Bildalter %1 ms</translation>
    </message>
    <message>
        <source>frame age %1 ms (since arrival)</source>
        <translation>Bildalter %1 ms (seit Empfang)</translation>
    </message>
</context>
<context>
    <name>ocu::VideoWatchdog</name>
    <message>
        <source>video %1</source>
        <translation>Video %1</translation>
    </message>
    <message>
        <source>video frame %1 ms old (limit %2 ms)</source>
        <translation>Videobild %1 ms alt (Grenze %2 ms)</translation>
    </message>
    <message>
        <source>VIDEO WATCHDOG stopped driving (%1); video is back: press Resume driving</source>
        <translation>VIDEO-WATCHDOG hat das Fahren gestoppt (%1); Video ist zurück: „Fahren fortsetzen“ drücken</translation>
    </message>
    <message>
        <source>VIDEO WATCHDOG stopped driving: %1</source>
        <translation>VIDEO-WATCHDOG hat das Fahren gestoppt: %1</translation>
    </message>
    <message>
        <source>Driving waits for video (%1)</source>
        <translation>Fahren wartet auf Video (%1)</translation>
    </message>
</context>
<context>
    <name>ocu::VirtualStick</name>
    <message>
        <source>Drag to drive: up = forward, right = turn right. Release to stop.</source>
        <translation>Ziehen zum Fahren: oben = vorwärts, rechts = rechts drehen. Loslassen zum Anhalten.</translation>
    </message>
    <message>
        <source>fwd</source>
        <translation>vor</translation>
    </message>
</context>
<context>
    <name>ocu::WorkspaceBar</name>
    <message>
        <source>Workspaces</source>
        <translation>Arbeitsbereiche</translation>
    </message>
    <message>
        <source>%1 workspace (%2)</source>
        <translation>Arbeitsbereich %1 (%2)</translation>
    </message>
    <message>
        <source>Dispatch</source>
        <translation>Disposition</translation>
    </message>
    <message>
        <source>Compaction</source>
        <translation>Verdichtung</translation>
    </message>
    <message>
        <source>UGV</source>
        <translation>UGV</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Beobachten</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Alle</translation>
    </message>
</context>
<context>
    <name>ocu::recording::Recorder</name>
    <message numerus="yes">
        <source>Flight recorder behind: %n record(s) dropped (%1 in all)</source>
        <translation>
            <numerusform>Flugschreiber im Rückstand: %n Eintrag verworfen (insgesamt %1)</numerusform>
            <numerusform>Flugschreiber im Rückstand: %n Einträge verworfen (insgesamt %1)</numerusform>
        </translation>
    </message>
    <message>
        <source>the recorder is already running</source>
        <translation>der Flugschreiber läuft bereits</translation>
    </message>
    <message>
        <source>%1 exists already; a recording is never overwritten</source>
        <translation>%1 existiert bereits; eine Aufzeichnung wird nie überschrieben</translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>%1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>kein Speicher mehr</translation>
    </message>
    <message>
        <source>cannot create the recording schema in %1: %2</source>
        <translation>das Aufzeichnungsschema kann in %1 nicht angelegt werden: %2</translation>
    </message>
</context>
</TS>

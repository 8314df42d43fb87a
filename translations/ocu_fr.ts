<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>CommandLine</name>
    <message>
        <source>Mixed-fleet Operator Control Unit: JAUS ground vehicles, ISO 23725 autonomous haulage and OSYRIS rollers and pavers on one console.
Without --config it starts on the built-in simulated site.</source>
        <translation>Poste de commande opérateur pour flottes mixtes : véhicules terrestres JAUS, transport autonome ISO 23725, compacteurs et finisseurs OSYRIS sur une seule console.
Sans --config, il démarre sur le site simulé intégré.</translation>
    </message>
    <message>
        <source>Site configuration (JSON, see docs/site-config.md). Default: the built-in simulated site.</source>
        <translation>Configuration du site (JSON, voir docs/site-config.md). Par défaut : le site simulé intégré.</translation>
    </message>
    <message>
        <source>Do not start the built-in simulators, even if the configuration enables them.</source>
        <translation>Ne pas démarrer les simulateurs intégrés, même si la configuration les active.</translation>
    </message>
    <message>
        <source>Write a PNG screenshot to FILE after --settle seconds, then exit 0.</source>
        <translation>Écrire une capture d&apos;écran PNG dans FILE après --settle secondes, puis quitter avec 0.</translation>
    </message>
    <message>
        <source>What --screenshot captures: all (the whole window) or one panel: %1.</source>
        <translation>Ce que capture --screenshot : all (toute la fenêtre) ou un panneau : %1.</translation>
    </message>
    <message>
        <source>Window size for the screenshot, e.g. 1600x1000.</source>
        <translation>Taille de la fenêtre pour la capture, p. ex. 1600x1000.</translation>
    </message>
    <message>
        <source>Seconds to let live data arrive before the screenshot (default 3).</source>
        <translation>Secondes d&apos;attente des données en direct avant la capture (3 par défaut).</translation>
    </message>
    <message>
        <source>User interface language: en, de or fr (default: the system locale).</source>
        <translation>Langue de l&apos;interface : en, de ou fr (par défaut : paramètres régionaux du système).</translation>
    </message>
    <message>
        <source>Enable debug output for these logging categories, comma-separated: ocu.jaus, ocu.iso, ocu.osyris, ocu.ui, ocu.sim, ocu.* (Qt wildcard rules).</source>
        <translation>Activer la sortie de débogage pour ces catégories de journalisation, séparées par des virgules : ocu.jaus, ocu.iso, ocu.osyris, ocu.ui, ocu.sim, ocu.* (règles génériques Qt).</translation>
    </message>
    <message>
        <source>No window: print one JSON line per machine change and per event on stdout, read JSON-line commands on stdin (see README).</source>
        <translation>Sans fenêtre : écrire une ligne JSON par changement de machine et par événement sur stdout, lire des commandes en lignes JSON sur stdin (voir README).</translation>
    </message>
    <message>
        <source>With --headless: stop after SECONDS (default: run until stdin closes).</source>
        <translation>Avec --headless : s&apos;arrêter après SECONDS (par défaut : jusqu&apos;à la fermeture de stdin).</translation>
    </message>
    <message>
        <source>Start with the default panel layout instead of the saved one.</source>
        <translation>Démarrer avec la disposition par défaut des panneaux au lieu de celle enregistrée.</translation>
    </message>
    <message>
        <source>Unexpected argument: %1</source>
        <translation>Argument inattendu : %1</translation>
    </message>
    <message>
        <source>--view: unknown view &quot;%1&quot;; use all, %2</source>
        <translation>--view : vue inconnue « %1 » ; utiliser all, %2</translation>
    </message>
    <message>
        <source>--size: expected WxH such as 1600x1000, got &quot;%1&quot;</source>
        <translation>--size : WxH attendu, p. ex. 1600x1000, reçu « %1 »</translation>
    </message>
    <message>
        <source>--size: %1 is outside 320x240 .. 8192x8192</source>
        <translation>--size : %1 est hors de 320x240 .. 8192x8192</translation>
    </message>
    <message>
        <source>--settle: expected seconds between 0 and 3600, got &quot;%1&quot;</source>
        <translation>--settle : secondes entre 0 et 3600 attendues, reçu « %1 »</translation>
    </message>
    <message>
        <source>--lang: &quot;%1&quot; is not one of en, de, fr</source>
        <translation>--lang : « %1 » n&apos;est pas en, de ou fr</translation>
    </message>
    <message>
        <source>--duration: expected seconds &gt;= 0, got &quot;%1&quot;</source>
        <translation>--duration : secondes &gt;= 0 attendues, reçu « %1 »</translation>
    </message>
    <message>
        <source>--headless and --screenshot cannot be combined</source>
        <translation>--headless et --screenshot ne peuvent pas être combinés</translation>
    </message>
    <message>
        <source>Check the site configuration FILE, print each problem as file:line, start nothing; exit 0 when valid, 1 when not.</source>
        <translation>Vérifier la configuration du site FILE, afficher chaque problème sous la forme fichier:ligne, ne rien démarrer ; code de sortie 0 si valide, 1 sinon.</translation>
    </message>
    <message>
        <source>all:PANEL: the whole window with that panel in front.</source>
        <translation>all:PANEL : toute la fenêtre avec ce panneau au premier plan.</translation>
    </message>
    <message>
        <source>With --headless: also take JSON-line commands on a local socket at PATH (mode 0660: owner and group); the run then ends on SIGTERM or --duration, not at the end of stdin.</source>
        <translation>Avec --headless : accepter aussi des commandes en lignes JSON sur un socket local à PATH (mode 0660 : propriétaire et groupe) ; l&apos;exécution se termine alors sur SIGTERM ou --duration, et non à la fin de stdin.</translation>
    </message>
    <message>
        <source>With --headless: write the shift report as PDF to FILE when the run ends.</source>
        <translation>Avec --headless : écrire le rapport de poste en PDF dans FILE à la fin de l&apos;exécution.</translation>
    </message>
    <message>
        <source>With --headless: write the shift report as CSV to FILE when the run ends.</source>
        <translation>Avec --headless : écrire le rapport de poste en CSV dans FILE à la fin de l&apos;exécution.</translation>
    </message>
    <message>
        <source>Start with the night palette.</source>
        <translation>Démarrer avec la palette de nuit.</translation>
    </message>
    <message>
        <source>--workspace: &quot;%1&quot; is not one of dispatch, compaction, ugv, monitor, all</source>
        <translation>--workspace : « %1 » n&apos;est pas dispatch, compaction, ugv, monitor ou all</translation>
    </message>
    <message>
        <source>--command-socket needs --headless</source>
        <translation>--command-socket nécessite --headless</translation>
    </message>
    <message>
        <source>--shift-report/--shift-csv need --headless (in the window: Production panel, Shift report)</source>
        <translation>--shift-report/--shift-csv nécessitent --headless (dans la fenêtre : panneau Production, Rapport de poste)</translation>
    </message>
</context>
<context>
    <name>CommandResult</name>
    <message>
        <source>no target: nothing sent</source>
        <translation>aucune cible : rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>sent to %1</source>
        <translation>envoyé à %1</translation>
    </message>
    <message>
        <source>NOT sent: %1</source>
        <translation>NON envoyé : %1</translation>
    </message>
    <message>
        <source>sent to %1; NOT sent: %2</source>
        <translation>envoyé à %1 ; NON envoyé : %2</translation>
    </message>
</context>
<context>
    <name>ConsoleApp</name>
    <message>
        <source>The site configuration was refused:
%1</source>
        <translation>La configuration du site a été refusée :
%1</translation>
    </message>
    <message>
        <source>Operator Control Unit</source>
        <translation>Poste de commande opérateur</translation>
    </message>
    <message>
        <source>Operator Control Unit — %1</source>
        <translation>Poste de commande opérateur — %1</translation>
    </message>
    <message>
        <source>%1: the site configuration is valid (%2)</source>
        <translation>%1 : la configuration du site est valide (%2)</translation>
    </message>
</context>
<context>
    <name>HeadlessSocket</name>
    <message>
        <source>%1: another console answers on this command socket</source>
        <translation>%1 : une autre console répond déjà sur ce socket de commandes</translation>
    </message>
    <message>
        <source>%1: cannot open the command socket: %2</source>
        <translation>%1 : impossible d&apos;ouvrir le socket de commandes : %2</translation>
    </message>
    <message>
        <source>%1: cannot set the command socket&apos;s mode</source>
        <translation>%1 : impossible de définir le mode du socket de commandes</translation>
    </message>
</context>
<context>
    <name>JausModule</name>
    <message>
        <source>mission_upload: %1; nothing sent</source>
        <translation>mission_upload : %1 ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>Replay: the missions as the vehicles reported them then; commands are disabled.</source>
        <translation>Relecture : les missions telles que les véhicules les signalaient alors ; les commandes sont désactivées.</translation>
    </message>
    <message>
        <source>Recorded mission</source>
        <translation>Mission enregistrée</translation>
    </message>
</context>
<context>
    <name>MissionReplayBridge</name>
    <message>
        <source>replay: commands are disabled</source>
        <translation>relecture : les commandes sont désactivées</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Compaction design not loaded: %1</source>
        <translation>Projet de compactage non chargé : %1</translation>
    </message>
    <message>
        <source>Queue</source>
        <translation>Attente</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Mise en place</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Chargement</translation>
    </message>
    <message>
        <source>Haul</source>
        <translation>Transport</translation>
    </message>
    <message>
        <source>Dump</source>
        <translation>Déversement</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>Retour</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>Autre</translation>
    </message>
    <message>
        <source>Tonnes over the shift: %1 t in %2 loads</source>
        <translation>Tonnes sur le poste : %1 t en %2 chargements</translation>
    </message>
    <message>
        <source>Dumped (t)</source>
        <translation>Déversé (t)</translation>
    </message>
    <message>
        <source>Plan (t, %1 t/shift)</source>
        <translation>Plan (t, %1 t/poste)</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>Cycle time breakdown (average minutes per cycle)</source>
        <translation>Répartition du temps de cycle (minutes moyennes par cycle)</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d&apos;écrire %1 : %2</translation>
    </message>
    <message>
        <source>Shift report</source>
        <translation>Rapport de poste</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <source>Shift report — %1</source>
        <translation>Rapport de poste — %1</translation>
    </message>
    <message>
        <source>Shift %1 to %2 · written %3</source>
        <translation>Poste de %1 à %2 · écrit %3</translation>
    </message>
    <message>
        <source>plan %1 t for the shift, %2 t due by now (%3 %)</source>
        <translation>plan %1 t pour le poste, %2 t dues à ce stade (%3 %)</translation>
    </message>
    <message>
        <source>no plan set</source>
        <translation>aucun plan défini</translation>
    </message>
    <message>
        <source>%1 loads, %2 t dumped, %3 cycles, average cycle %4 · %5</source>
        <translation>%1 chargements, %2 t déversées, %3 cycles, cycle moyen %4 · %5</translation>
    </message>
    <message>
        <source>%1 loads were dumped without a reported weight (not in the tonnes)</source>
        <translation>%1 chargements ont été déversés sans poids signalé (non comptés dans les tonnes)</translation>
    </message>
    <message>
        <source>(no site map available for the snapshot)</source>
        <translation>(aucun plan du site disponible pour l&apos;instantané)</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>Chargements</translation>
    </message>
    <message>
        <source>Tonnes</source>
        <translation>Tonnes</translation>
    </message>
    <message>
        <source>t/load</source>
        <translation>t/chargement</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Cycle</translation>
    </message>
    <message>
        <source>Shift</source>
        <translation>Poste</translation>
    </message>
    <message>
        <source>Trucks (cycle parts: average min:s per cycle)</source>
        <translation>Camions (parties du cycle : min:s moyennes par cycle)</translation>
    </message>
    <message>
        <source>Shovels (load areas)</source>
        <translation>Pelles (zones de chargement)</translation>
    </message>
    <message>
        <source>Dumps and crusher</source>
        <translation>Déversements et concasseur</translation>
    </message>
</context>
<context>
    <name>Recording</name>
    <message>
        <source>%1: no such file</source>
        <translation>%1 : fichier introuvable</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1 : impossible d&apos;ouvrir : %2</translation>
    </message>
    <message>
        <source>%1 is not an OCU recording (%2)</source>
        <translation>%1 n&apos;est pas un enregistrement OCU (%2)</translation>
    </message>
    <message>
        <source>%1 is not an OCU recording</source>
        <translation>%1 n&apos;est pas un enregistrement OCU</translation>
    </message>
    <message>
        <source>%1: recording schema %2 is not supported</source>
        <translation>%1 : le schéma d&apos;enregistrement %2 n&apos;est pas pris en charge</translation>
    </message>
    <message>
        <source> - not every target reached</source>
        <translation> - toutes les cibles n&apos;ont pas été atteintes</translation>
    </message>
    <message>
        <source>the output is not writable</source>
        <translation>la sortie n&apos;est pas accessible en écriture</translation>
    </message>
    <message>
        <source>write failed: %1</source>
        <translation>échec de l&apos;écriture : %1</translation>
    </message>
    <message>
        <source>%1 exists already</source>
        <translation>%1 existe déjà</translation>
    </message>
    <message>
        <source>the window ends before it starts</source>
        <translation>la fenêtre se termine avant de commencer</translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>impossible de créer %1 : %2</translation>
    </message>
    <message>
        <source>slice to %1 failed: %2</source>
        <translation>échec de l&apos;extraction vers %1 : %2</translation>
    </message>
</context>
<context>
    <name>Replay</name>
    <message>
        <source>Replay: acknowledgements are replayed, not made</source>
        <translation>Relecture : les acquittements sont rejoués, pas effectués</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Relecture</translation>
    </message>
    <message>
        <source>REPLAY — %1 — recorded %2 to %3 UTC — not live, commands disabled</source>
        <translation>RELECTURE — %1 — enregistré de %2 à %3 UTC — pas en direct, commandes désactivées</translation>
    </message>
    <message>
        <source>Replay: commands are disabled</source>
        <translation>Relecture : les commandes sont désactivées</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Chronologie</translation>
    </message>
    <message>
        <source>This recording holds no pass counts.</source>
        <translation>Cet enregistrement ne contient aucun nombre de passes.</translation>
    </message>
    <message>
        <source>Replay: commands are disabled. This panel acts on live machines only.</source>
        <translation>Relecture : les commandes sont désactivées. Ce panneau n&apos;agit que sur des machines en direct.</translation>
    </message>
    <message>
        <source>--from/--to: not a time</source>
        <translation>--from/--to : pas une heure</translation>
    </message>
    <message>
        <source>--at: &quot;%1&quot; is not a time</source>
        <translation>--at : « %1 » n&apos;est pas une heure</translation>
    </message>
    <message>
        <source>Operator Control Unit — REPLAY %1</source>
        <translation>Poste de commande opérateur — RELECTURE %1</translation>
    </message>
</context>
<context>
    <name>Screenshot</name>
    <message>
        <source>unknown view &quot;%1&quot;</source>
        <translation>vue inconnue « %1 »</translation>
    </message>
    <message>
        <source>nothing to grab for view &quot;%1&quot;</source>
        <translation>rien à capturer pour la vue « %1 »</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d&apos;écrire %1 : %2</translation>
    </message>
</context>
<context>
    <name>SiteLoader</name>
    <message>
        <source>%1: cannot open the site configuration: %2</source>
        <translation>%1 : impossible d&apos;ouvrir la configuration du site : %2</translation>
    </message>
    <message>
        <source>%1: larger than 64 MiB</source>
        <translation>%1 : plus de 64 Mio</translation>
    </message>
</context>
<context>
    <name>ocu</name>
    <message>
        <source>Folder for this run&apos;s flight recording (default: record.dir of the site configuration, else the user&apos;s data folder).</source>
        <translation>Dossier de l&apos;enregistrement de vol de cette exécution (par défaut : record.dir de la configuration du site, sinon le dossier de données de l&apos;utilisateur).</translation>
    </message>
    <message>
        <source>Do not record this run.</source>
        <translation>Ne pas enregistrer cette exécution.</translation>
    </message>
    <message>
        <source>Replay a flight recording (no protocol stacks, commands disabled).</source>
        <translation>Relire un enregistrement de vol (aucune pile de protocole, commandes désactivées).</translation>
    </message>
    <message>
        <source>With --replay: start at T (seconds after the start, HH:MM:SS UTC or ISO 8601).</source>
        <translation>Avec --replay : commencer à T (secondes après le début, HH:MM:SS UTC ou ISO 8601).</translation>
    </message>
    <message>
        <source>With --replay: playing speed 0.1 to 16 (--headless: default as fast as possible).</source>
        <translation>Avec --replay : vitesse de lecture de 0,1 à 16 (--headless : par défaut aussi vite que possible).</translation>
    </message>
    <message>
        <source>With --replay: write the window --from/--to as JSON lines and exit.</source>
        <translation>Avec --replay : écrire la fenêtre --from/--to en lignes JSON et quitter.</translation>
    </message>
    <message>
        <source>With --replay: write machine states of the window as CSV and exit.</source>
        <translation>Avec --replay : écrire les états des machines de la fenêtre en CSV et quitter.</translation>
    </message>
    <message>
        <source>With --replay: write the window as a new recording and exit.</source>
        <translation>Avec --replay : écrire la fenêtre comme nouvel enregistrement et quitter.</translation>
    </message>
    <message>
        <source>Start of the export window (as --at).</source>
        <translation>Début de la fenêtre d&apos;export (comme --at).</translation>
    </message>
    <message>
        <source>End of the export window (as --at).</source>
        <translation>Fin de la fenêtre d&apos;export (comme --at).</translation>
    </message>
    <message>
        <source>Start in this workspace: dispatch, compaction, ugv, monitor or all (default: the one last used, else the operator&apos;s role&apos;s).</source>
        <translation>Démarrer dans cet espace de travail : dispatch, compaction, ugv, monitor ou all (par défaut : le dernier utilisé, sinon celui du rôle de l&apos;opérateur).</translation>
    </message>
    <message>
        <source>--speed: expected 0.1 to 16, got &quot;%1&quot;</source>
        <translation>--speed : 0,1 à 16 attendu, reçu « %1 »</translation>
    </message>
    <message>
        <source>--at, --speed, --export-* and --from/--to need --replay FILE</source>
        <translation>--at, --speed, --export-* et --from/--to nécessitent --replay FILE</translation>
    </message>
</context>
<context>
    <name>ocu::AlarmModel</name>
    <message>
        <source>link %1 lost%2</source>
        <translation>liaison %1 perdue%2</translation>
    </message>
    <message>
        <source>link %1 restored</source>
        <translation>liaison %1 rétablie</translation>
    </message>
    <message>
        <source>no data from %1</source>
        <translation>aucune donnée de %1</translation>
    </message>
    <message>
        <source>health fault</source>
        <translation>défaut de santé</translation>
    </message>
    <message>
        <source>Time (UTC)</source>
        <translation>Heure (UTC)</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Gravité</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Ack</source>
        <translation>Acq.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>oui</translation>
    </message>
    <message>
        <source>NO</source>
        <translation>NON</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Priorité</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>shelved until %1</source>
        <translation>mise en attente jusqu&apos;à %1</translation>
    </message>
    <message>
        <source>
… and %1 more</source>
        <translation>
… et %1 de plus</translation>
    </message>
</context>
<context>
    <name>ocu::AutoDispatcher</name>
    <message>
        <source>way %1</source>
        <translation>voie %1</translation>
    </message>
    <message>
        <source>Auto dispatch ON (%1): idle FMS trucks go to the shortest queue</source>
        <translation>Répartition automatique ACTIVÉE (%1) : les camions FMS libres vont vers la file d&apos;attente la plus courte</translation>
    </message>
    <message>
        <source>Auto dispatch OFF (%1)</source>
        <translation>Répartition automatique DÉSACTIVÉE (%1)</translation>
    </message>
    <message>
        <source>Auto dispatch: %1</source>
        <translation>Répartition automatique : %1</translation>
    </message>
    <message>
        <source>%1 rejected way %2: %3</source>
        <translation>%1 a refusé la voie %2 : %3</translation>
    </message>
    <message>
        <source>%1 did not report the assignment to way %2 within %3 s</source>
        <translation>%1 n&apos;a pas signalé l&apos;affectation à la voie %2 dans les %3 s</translation>
    </message>
    <message>
        <source>%1: %2 at %3 (queue %4)</source>
        <translation>%1 : %2 à %3 (file %4)</translation>
    </message>
    <message>
        <source>%1 — sent</source>
        <translation>%1 — envoyé</translation>
    </message>
    <message>
        <source>%1 — NOT sent: %2</source>
        <translation>%1 — NON envoyé : %2</translation>
    </message>
</context>
<context>
    <name>ocu::AxisDisplay</name>
    <message>
        <source>forward</source>
        <translation>avant</translation>
    </message>
    <message>
        <source>turn</source>
        <translation>rotation</translation>
    </message>
    <message>
        <source>axis %1</source>
        <translation>axe %1</translation>
    </message>
</context>
<context>
    <name>ocu::CommandGate</name>
    <message>
        <source>protocol stack</source>
        <translation>pile de protocole</translation>
    </message>
    <message>
        <source>stack did not answer within %1 ms</source>
        <translation>la pile n&apos;a pas répondu dans les %1 ms</translation>
    </message>
    <message>
        <source>no protocol bridge registered: nothing sent</source>
        <translation>aucune passerelle de protocole enregistrée : rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>unknown machine %1</source>
        <translation>machine inconnue %1</translation>
    </message>
    <message>
        <source>the console is locked: only stops are accepted</source>
        <translation>la console est verrouillée : seuls les arrêts sont acceptés</translation>
    </message>
    <message>
        <source>release needs a deliberate confirmation</source>
        <translation>la levée exige une confirmation délibérée</translation>
    </message>
    <message>
        <source>no %1 bridge in this console: nothing sent</source>
        <translation>aucune passerelle %1 dans cette console : rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>%1 already reports being stopped</source>
        <translation>%1 signale déjà être arrêté</translation>
    </message>
    <message>
        <source>%1 has not reported being stopped %2 ms after the stop command was sent</source>
        <translation>%1 n&apos;a pas signalé être arrêté %2 ms après l&apos;envoi de la commande d&apos;arrêt</translation>
    </message>
    <message>
        <source>%1: OSYRIS carries no stop state, so no machine can confirm the stop; the STOP text went to the drivers&apos; displays</source>
        <translation>%1 : OSYRIS ne transmet aucun état d&apos;arrêt, aucune machine ne peut donc confirmer l&apos;arrêt ; le texte STOP a été envoyé aux écrans des conducteurs</translation>
    </message>
    <message>
        <source>%1 %2 ms after the command</source>
        <translation>%1 %2 ms après la commande</translation>
    </message>
    <message>
        <source>%1 already reports the effect of %2</source>
        <translation>%1 signale déjà l&apos;effet de %2</translation>
    </message>
    <message>
        <source>%1 has not confirmed %2 %3 ms after the command was sent</source>
        <translation>%1 n&apos;a pas confirmé %2 %3 ms après l&apos;envoi de la commande</translation>
    </message>
</context>
<context>
    <name>ocu::CommandPermissionHint</name>
    <message>
        <source>Not permitted</source>
        <translation>Non autorisé</translation>
    </message>
</context>
<context>
    <name>ocu::CommandPermissions</name>
    <message>
        <source>monitor</source>
        <translation>observateur</translation>
    </message>
    <message>
        <source>dispatcher</source>
        <translation>répartiteur</translation>
    </message>
    <message>
        <source>site manager</source>
        <translation>chef de site</translation>
    </message>
    <message>
        <source>UGV operator</source>
        <translation>opérateur UGV</translation>
    </message>
    <message>
        <source>supervisor</source>
        <translation>superviseur</translation>
    </message>
    <message>
        <source>admin</source>
        <translation>administrateur</translation>
    </message>
    <message>
        <source>%1 is not permitted to any role at this console</source>
        <translation>%1 n&apos;est autorisé à aucun rôle sur cette console</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 ou %2</translation>
    </message>
    <message>
        <source>%1 needs the %2 role (you are %3)</source>
        <translation>%1 nécessite le rôle %2 (vous êtes %3)</translation>
    </message>
    <message>
        <source>Not permitted to any role at this console</source>
        <translation>Autorisé à aucun rôle sur cette console</translation>
    </message>
    <message>
        <source>Needs the %1 role (you are %2)</source>
        <translation>Nécessite le rôle %1 (vous êtes %2)</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionMapOverlay</name>
    <message>
        <source>New area: %1 points (3 needed)</source>
        <translation>Nouvelle zone : %1 points (3 nécessaires)</translation>
    </message>
    <message>
        <source>New area: %1 points, %2 m²</source>
        <translation>Nouvelle zone : %1 points, %2 m²</translation>
    </message>
    <message>
        <source>click adds a point · Enter, double click or the first point closes · Backspace undoes · Esc cancels</source>
        <translation>un clic ajoute un point · Entrée, double clic ou le premier point ferme · Retour arrière annule · Échap abandonne</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionPanel</name>
    <message>
        <source>Lift:</source>
        <translation>Couche :</translation>
    </message>
    <message>
        <source>Top view</source>
        <translation>Vue de dessus</translation>
    </message>
    <message>
        <source>Areas</source>
        <translation>Zones</translation>
    </message>
    <message>
        <source>Stations</source>
        <translation>Profils</translation>
    </message>
    <message>
        <source>Draw area</source>
        <translation>Dessiner une zone</translation>
    </message>
    <message>
        <source>Draw a compaction area on the 2D map: click to add points; Enter, a double click or a click on the first point closes; Backspace undoes; Esc cancels</source>
        <translation>Dessiner une zone de compactage sur la carte 2D : cliquer pour ajouter des points ; Entrée, un double clic ou un clic sur le premier point ferme ; Retour arrière annule ; Échap abandonne</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Coverage report…</source>
        <translation>Rapport de couverture…</translation>
    </message>
    <message>
        <source>PDF, Veta-style CSV and GeoTIFF of the pass counts, in the site&apos;s projected CRS</source>
        <translation>PDF, CSV de style Veta et GeoTIFF des nombres de passes, dans le SCR projeté du site</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>Covered %</source>
        <translation>Couvert %</translation>
    </message>
    <message>
        <source>Target %</source>
        <translation>Dans la cible %</translation>
    </message>
    <message>
        <source>Under %</source>
        <translation>Sous %</translation>
    </message>
    <message>
        <source>Over %</source>
        <translation>Au-dessus %</translation>
    </message>
    <message>
        <source>Incompl.</source>
        <translation>Incompl.</translation>
    </message>
    <message>
        <source>Covered cells within the target passes, % of the area</source>
        <translation>Cellules couvertes dont les passes sont dans la cible, en % de la zone</translation>
    </message>
    <message>
        <source>Cells a given-up ribbon gap may have passed over: their counts are lower bounds</source>
        <translation>Cellules qu&apos;une lacune abandonnée du ruban a pu parcourir : leurs nombres sont des minorants</translation>
    </message>
    <message>
        <source>From</source>
        <translation>De</translation>
    </message>
    <message>
        <source>Covered cells within the target passes, % of the range&apos;s band</source>
        <translation>Cellules couvertes dont les passes sont dans la cible, en % de la bande de l&apos;intervalle</translation>
    </message>
    <message>
        <source>Pick a range to outline it on the map; double click to show it</source>
        <translation>Choisir un intervalle pour le tracer sur la carte ; double-cliquer pour l&apos;afficher</translation>
    </message>
    <message>
        <source>Cancel drawing</source>
        <translation>Annuler le dessin</translation>
    </message>
    <message>
        <source>Area &quot;%1&quot; removed.</source>
        <translation>Zone « %1 » supprimée.</translation>
    </message>
    <message>
        <source>Double click an area to show it on the map</source>
        <translation>Double-cliquer sur une zone pour l&apos;afficher sur la carte</translation>
    </message>
    <message>
        <source>Design: %1 — %2 alignment(s), %3 boundary(ies)%4</source>
        <translation>Projet : %1 — %2 axe(s), %3 limite(s)%4</translation>
    </message>
    <message>
        <source> · %1 warning(s): %2</source>
        <translation> · %1 avertissement(s) : %2</translation>
    </message>
    <message>
        <source>No design loaded (site configuration &quot;compaction&quot;: {&quot;design&quot;: …}).</source>
        <translation>Aucun projet chargé (configuration du site &quot;compaction&quot;: {&quot;design&quot;: …}).</translation>
    </message>
    <message>
        <source>Lift %1 (z %2 … %3 m)</source>
        <translation>Couche %1 (z %2 … %3 m)</translation>
    </message>
    <message>
        <source>%1 (design)</source>
        <translation>%1 (projet)</translation>
    </message>
    <message>
        <source>No station ranges: the alignment cannot be placed (no EPSG code or worksite frame).</source>
        <translation>Aucun intervalle de profils : l&apos;axe ne peut pas être placé (pas de code EPSG ni de repère de chantier).</translation>
    </message>
    <message>
        <source>No station ranges without a design alignment.</source>
        <translation>Aucun intervalle de profils sans axe dans le projet.</translation>
    </message>
    <message>
        <source>Every %1 m along %2 (%3 m left, %4 m right)</source>
        <translation>Tous les %1 m le long de %2 (%3 m à gauche, %4 m à droite)</translation>
    </message>
    <message>
        <source>the alignment</source>
        <translation>l&apos;axe</translation>
    </message>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>Area %1</source>
        <translation>Zone %1</translation>
    </message>
    <message>
        <source>New compaction area</source>
        <translation>Nouvelle zone de compactage</translation>
    </message>
    <message>
        <source>Name of the area:</source>
        <translation>Nom de la zone :</translation>
    </message>
    <message>
        <source>The drawn area was discarded.</source>
        <translation>La zone dessinée a été abandonnée.</translation>
    </message>
    <message>
        <source>Replace area</source>
        <translation>Remplacer la zone</translation>
    </message>
    <message>
        <source>An area named &quot;%1&quot; exists. Replace it with the new outline?</source>
        <translation>Une zone nommée « %1 » existe. La remplacer par le nouveau contour ?</translation>
    </message>
    <message>
        <source>Area &quot;%1&quot; saved to %2.</source>
        <translation>Zone « %1 » enregistrée dans %2.</translation>
    </message>
    <message>
        <source>Coverage report not written.</source>
        <translation>Rapport de couverture non écrit.</translation>
    </message>
    <message>
        <source>Written: %1 (%2.*).</source>
        <translation>Écrit : %1 (%2.*).</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Échec : %1</translation>
    </message>
    <message>
        <source>Coverage report</source>
        <translation>Rapport de couverture</translation>
    </message>
    <message>
        <source>coverage-report.pdf</source>
        <translation>rapport-couverture.pdf</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
</context>
<context>
    <name>ocu::CompactionSession</name>
    <message>
        <source>cannot open %1: %2</source>
        <translation>impossible d&apos;ouvrir %1 : %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB</source>
        <translation>%1 dépasse %2 Mio</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>the design names no EPSG code (CoordinateSystem/@epsgCode): it cannot be placed on the map</source>
        <translation>le projet n&apos;indique aucun code EPSG (CoordinateSystem/@epsgCode) : il ne peut pas être placé sur la carte</translation>
    </message>
    <message>
        <source>an area needs a name</source>
        <translation>une zone doit avoir un nom</translation>
    </message>
    <message>
        <source>an area needs at least 3 points</source>
        <translation>une zone doit avoir au moins 3 points</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>impossible de lire %1 : %2</translation>
    </message>
    <message>
        <source>%1 is not valid JSON (%2): areas not saved</source>
        <translation>%1 n&apos;est pas un JSON valide (%2) : zones non enregistrées</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d&apos;écrire %1 : %2</translation>
    </message>
    <message>
        <source>no OSYRIS station in this console: no pass counts to report</source>
        <translation>aucune station OSYRIS dans cette console : aucun nombre de passes à rapporter</translation>
    </message>
</context>
<context>
    <name>ocu::ControlRoomModel</name>
    <message>
        <source>%1 at %2</source>
        <translation>%1 à %2</translation>
    </message>
    <message>
        <source>not seen since %1</source>
        <translation>non vu depuis %1</translation>
    </message>
    <message>
        <source>locked</source>
        <translation>verrouillé</translation>
    </message>
    <message>
        <source>signed in</source>
        <translation>connecté</translation>
    </message>
    <message>
        <source>controls machines as %1</source>
        <translation>commande les machines en tant que %1</translation>
    </message>
    <message>
        <source>%1 (this console)</source>
        <translation>%1 (cette console)</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Console</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Opérateur</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rôle</translation>
    </message>
    <message>
        <source>Since</source>
        <translation>Depuis</translation>
    </message>
    <message>
        <source>State</source>
        <translation>État</translation>
    </message>
</context>
<context>
    <name>ocu::ControlRoomPanel</name>
    <message>
        <source>Waiting for the control-room history…</source>
        <translation>En attente de l’historique de la salle de contrôle…</translation>
    </message>
    <message>
        <source>Control-room history unavailable since %1: the room as last seen. %2</source>
        <translation>Historique de la salle de contrôle indisponible depuis %1 : la salle telle que vue en dernier. %2</translation>
    </message>
</context>
<context>
    <name>ocu::CoverageReport</name>
    <message>
        <source>no pass counts yet</source>
        <translation>pas encore de nombres de passes</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d&apos;écrire %1 : %2</translation>
    </message>
    <message>
        <source>no area named &quot;%1&quot;</source>
        <translation>aucune zone nommée « %1 »</translation>
    </message>
    <message>
        <source>PROJ could not convert a cell to EPSG:%1</source>
        <translation>PROJ n&apos;a pas pu convertir une cellule vers EPSG:%1</translation>
    </message>
    <message>
        <source>design CRS: %1</source>
        <translation>SCR du projet : %1</translation>
    </message>
    <message>
        <source>GDAL has no GTiff driver</source>
        <translation>GDAL n&apos;a pas de pilote GTiff</translation>
    </message>
    <message>
        <source>PROJ could not convert the raster&apos;s corners</source>
        <translation>PROJ n&apos;a pas pu convertir les coins du raster</translation>
    </message>
    <message>
        <source>GDAL cannot create %1: %2</source>
        <translation>GDAL ne peut pas créer %1 : %2</translation>
    </message>
    <message>
        <source>GDAL does not know EPSG:%1</source>
        <translation>GDAL ne connaît pas EPSG:%1</translation>
    </message>
    <message>
        <source>GDAL cannot write %1: %2</source>
        <translation>GDAL ne peut pas écrire %1 : %2</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Passes</translation>
    </message>
    <message>
        <source> (target)</source>
        <translation> (cible)</translation>
    </message>
    <message>
        <source>incomplete</source>
        <translation>incomplet</translation>
    </message>
    <message>
        <source>vibration on only</source>
        <translation>vibration active uniquement</translation>
    </message>
    <message>
        <source>vibration off only</source>
        <translation>vibration coupée uniquement</translation>
    </message>
    <message>
        <source>vibration on or off</source>
        <translation>vibration active ou coupée</translation>
    </message>
    <message>
        <source>forward passes only</source>
        <translation>passes avant uniquement</translation>
    </message>
    <message>
        <source>backward passes only</source>
        <translation>passes arrière uniquement</translation>
    </message>
    <message>
        <source>both directions</source>
        <translation>les deux sens</translation>
    </message>
    <message>
        <source>speed %1 … %2 m/s</source>
        <translation>vitesse %1 … %2 m/s</translation>
    </message>
    <message>
        <source>time %1 … %2</source>
        <translation>heure %1 … %2</translation>
    </message>
    <message>
        <source>machines %1 only</source>
        <translation>machines %1 uniquement</translation>
    </message>
    <message>
        <source>Compaction coverage report</source>
        <translation>Rapport de couverture du compactage</translation>
    </message>
    <message>
        <source>Compaction coverage report — %1</source>
        <translation>Rapport de couverture du compactage — %1</translation>
    </message>
    <message>
        <source>Written %1 · %2 · cell %3 m · target %4–%5 passes</source>
        <translation>Écrit %1 · %2 · cellule %3 m · cible %4–%5 passes</translation>
    </message>
    <message>
        <source>CRS: EPSG:%1 (%2) · design: %3</source>
        <translation>SCR : EPSG:%1 (%2) · projet : %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>Machines: %1 · data %2</source>
        <translation>Machines : %1 · données %2</translation>
    </message>
    <message>
        <source>none known</source>
        <translation>aucune connue</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 à %2</translation>
    </message>
    <message>
        <source>time range not known</source>
        <translation>période inconnue</translation>
    </message>
    <message>
        <source>Filters: %1</source>
        <translation>Filtres : %1</translation>
    </message>
    <message>
        <source>%1: z %2 … %3 m</source>
        <translation>%1 : z %2 … %3 m</translation>
    </message>
    <message>
        <source>Lifts (thickness %1): %2</source>
        <translation>Couches (épaisseur %1) : %2</translation>
    </message>
    <message>
        <source>off</source>
        <translation>désactivée</translation>
    </message>
    <message>
        <source>machine %1: %2 slot ranges</source>
        <translation>machine %1 : %2 plages de slots</translation>
    </message>
    <message>
        <source>INCOMPLETE: %1 cells may be under-counted: ribbon data that never arrived was given up (%2). Their counts are lower bounds.</source>
        <translation>INCOMPLET : %1 cellules peuvent être sous-comptées : des données de ruban jamais arrivées ont été abandonnées (%2). Leurs nombres sont des minorants.</translation>
    </message>
    <message>
        <source>Complete: every ribbon slot of every machine was received; no cell is marked incomplete.</source>
        <translation>Complet : chaque slot de ruban de chaque machine a été reçu ; aucune cellule n&apos;est marquée incomplète.</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Remarque : %1</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>m²</source>
        <translation>m²</translation>
    </message>
    <message>
        <source>covered %</source>
        <translation>couvert %</translation>
    </message>
    <message>
        <source>under %</source>
        <translation>sous %</translation>
    </message>
    <message>
        <source>at %</source>
        <translation>dans %</translation>
    </message>
    <message>
        <source>over %</source>
        <translation>au-dessus %</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>moyenne</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>Statistics per area</source>
        <translation>Statistiques par zone</translation>
    </message>
    <message>
        <source>All counted cells</source>
        <translation>Toutes les cellules comptées</translation>
    </message>
    <message>
        <source>Cells belong to an area when their centre lies inside it. covered = at least one pass; under/at/over the target as % of the area&apos;s cells; min/mean/max over covered cells.</source>
        <translation>Une cellule appartient à une zone quand son centre s&apos;y trouve. couvert = au moins une passe ; sous/dans/au-dessus de la cible en % des cellules de la zone ; min/moyenne/max sur les cellules couvertes.</translation>
    </message>
    <message>
        <source>Statistics per station range — %1, %2 m left to %3 m right of the centre line</source>
        <translation>Statistiques par intervalle de profils — %1, de %2 m à gauche à %3 m à droite de l&apos;axe</translation>
    </message>
    <message>
        <source>Stations</source>
        <translation>Profils</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <source>coverage report written</source>
        <translation>rapport de couverture écrit</translation>
    </message>
    <message>
        <source>give &quot;pdf&quot;, &quot;csv&quot; and/or &quot;geotiff&quot; (file names)</source>
        <translation>indiquer &quot;pdf&quot;, &quot;csv&quot; et/ou &quot;geotiff&quot; (noms de fichiers)</translation>
    </message>
    <message>
        <source>no pass counts yet (no OSYRIS station, or nothing counted)</source>
        <translation>pas encore de nombres de passes (aucune station OSYRIS, ou rien compté)</translation>
    </message>
    <message>
        <source>no lift %1 (the data has %2)</source>
        <translation>aucune couche %1 (les données en ont %2)</translation>
    </message>
    <message>
        <source>every lift</source>
        <translation>toutes les couches</translation>
    </message>
    <message>
        <source>top view (top-most lift per cell)</source>
        <translation>vue de dessus (couche la plus haute par cellule)</translation>
    </message>
    <message>
        <source>lift %1 (z %2 … %3 m)</source>
        <translation>couche %1 (z %2 … %3 m)</translation>
    </message>
    <message>
        <source>area &quot;%1&quot; has fewer than 3 usable vertices</source>
        <translation>la zone « %1 » a moins de 3 sommets utilisables</translation>
    </message>
    <message>
        <source>the design names no EPSG code: station ranges cannot be placed</source>
        <translation>le projet n&apos;indique aucun code EPSG : les intervalles de profils ne peuvent pas être placés</translation>
    </message>
</context>
<context>
    <name>ocu::CrewMessagesPanel</name>
    <message>
        <source>Send</source>
        <translation>Envoyer</translation>
    </message>
    <message>
        <source>Message to the crew (Enter sends)</source>
        <translation>Message à l&apos;équipe (Entrée envoie)</translation>
    </message>
    <message>
        <source>Recipient</source>
        <translation>Destinataire</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>Toutes les machines</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (sending…)</source>
        <translation>%1  → %2 : %3 (envoi…)</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (sent)</source>
        <translation>%1  → %2 : %3 (envoyé)</translation>
    </message>
    <message>
        <source>%1  → %2: %3 (NOT sent: %4)</source>
        <translation>%1  → %2 : %3 (NON envoyé : %4)</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchModel</name>
    <message>
        <source>link down</source>
        <translation>liaison coupée</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>voie %1</translation>
    </message>
    <message>
        <source>NEEDS ASSIGNMENT</source>
        <translation>AFFECTATION REQUISE</translation>
    </message>
    <message>
        <source>Reported assignment: %1</source>
        <translation>Affectation signalée : %1</translation>
    </message>
    <message>
        <source>Last request from this console: %1 to way %2 — %3</source>
        <translation>Dernière demande de cette console : %1 vers la voie %2 — %3</translation>
    </message>
    <message>
        <source>no answer yet</source>
        <translation>pas encore de réponse</translation>
    </message>
    <message>
        <source>Detail: %1</source>
        <translation>Détail : %1</translation>
    </message>
    <message>
        <source>The truck asks for work (or was handed back to the FMS).</source>
        <translation>Le camion demande du travail (ou a été rendu au FMS).</translation>
    </message>
    <message>
        <source>No route: %1</source>
        <translation>Aucun itinéraire : %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 m over %n way(s) (%2); %3</source>
        <translation>
            <numerusform>%1 m sur %n voie (%2) ; %3</numerusform>
            <numerusform>%1 m sur %n voies (%2) ; %3</numerusform>
        </translation>
    </message>
    <message>
        <source>route of the assignment</source>
        <translation>itinéraire de l&apos;affectation</translation>
    </message>
    <message>
        <source>shortest path</source>
        <translation>chemin le plus court</translation>
    </message>
    <message>
        <source>nominal 25 km/h (the truck is slower than 1 m/s)</source>
        <translation>25 km/h nominal (le camion roule à moins de 1 m/s)</translation>
    </message>
    <message>
        <source>at the reported speed</source>
        <translation>à la vitesse signalée</translation>
    </message>
    <message>
        <source>DispatchingCustodian: who dispatches this truck (only FMS trucks can be assigned)</source>
        <translation>DispatchingCustodian : qui répartit ce camion (seuls les camions FMS peuvent être affectés)</translation>
    </message>
    <message>
        <source>Truck</source>
        <translation>Camion</translation>
    </message>
    <message>
        <source>Custodian</source>
        <translation>Répartiteur</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Assignment</source>
        <translation>Affectation</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Tâche</translation>
    </message>
    <message>
        <source>Destination</source>
        <translation>Destination</translation>
    </message>
    <message>
        <source>ETA</source>
        <translation>Arrivée</translation>
    </message>
    <message>
        <source>Production</source>
        <translation>Production</translation>
    </message>
    <message>
        <source>Payload</source>
        <translation>Charge utile</translation>
    </message>
    <message>
        <source>In state</source>
        <translation>Dans l&apos;état</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchPanel</name>
    <message>
        <source>way %1</source>
        <translation>voie %1</translation>
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
        <translation>Touches du panneau de répartition :
Haut/Bas : choisir un camion dans le tableau (Alt+M : aller au tableau)
F6 : camion suivant qui a besoin d&apos;une affectation
Alt+T : tâche, Alt+D : destination (taper pour chercher), Alt+C : choisir la destination sur la carte 2D (cliquer une zone ; Échap annule)
Ctrl+Entrée ou Alt+A : affecter (réaffecter un camion qui a une tâche demande confirmation)
Alt+R : réinitialiser l&apos;affectation du camion (demande confirmation)
Alt+F : aller aux files d&apos;attente par pelle et déversement
Alt+U : répartition automatique activée/désactivée (l&apos;activation demande confirmation)</translation>
    </message>
    <message>
        <source>Truc&amp;ks</source>
        <translation>Ca&amp;mions</translation>
    </message>
    <message>
        <source>Next needing work (F6)</source>
        <translation>Suivant sans travail (F6)</translation>
    </message>
    <message>
        <source>Select the next truck that asks for work or was handed back to the FMS.</source>
        <translation>Sélectionner le camion suivant qui demande du travail ou a été rendu au FMS.</translation>
    </message>
    <message>
        <source>A&amp;uto dispatch</source>
        <translation>Répartition a&amp;uto</translation>
    </message>
    <message>
        <source>Assign every idle FMS truck automatically: empty to the shovel with the shortest queue, loaded to the dump with the shortest queue (Alt+U; switching on asks first).</source>
        <translation>Affecter automatiquement chaque camion FMS libre : vide vers la pelle avec la file la plus courte, chargé vers le déversement avec la file la plus courte (Alt+U ; l&apos;activation demande confirmation).</translation>
    </message>
    <message>
        <source>&amp;Queues</source>
        <translation>&amp;Files d&apos;attente</translation>
    </message>
    <message>
        <source>Queues per shovel and dump: trucks at the area and trucks coming to it</source>
        <translation>Files d&apos;attente par pelle et déversement : camions sur la zone et camions en route</translation>
    </message>
    <message>
        <source>&amp;Task</source>
        <translation>&amp;Tâche</translation>
    </message>
    <message>
        <source>&amp;Destination</source>
        <translation>&amp;Destination</translation>
    </message>
    <message>
        <source>Pick on &amp;map</source>
        <translation>Choisir sur la &amp;carte</translation>
    </message>
    <message>
        <source>Then click a load, dump, crusher, park or fuel area on the 2D map (Esc cancels).</source>
        <translation>Puis cliquer une zone de chargement, de déversement, de concasseur, de stationnement ou de carburant sur la carte 2D (Échap annule).</translation>
    </message>
    <message>
        <source>&amp;Assign</source>
        <translation>&amp;Affecter</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Réinitialiser</translation>
    </message>
    <message>
        <source>Reset the truck&apos;s assignment (HaulTruckAssignmentResetV1); asks first.</source>
        <translation>Réinitialiser l&apos;affectation du camion (HaulTruckAssignmentResetV1) ; demande confirmation.</translation>
    </message>
    <message>
        <source>Switch auto dispatch on?</source>
        <translation>Activer la répartition automatique ?</translation>
    </message>
    <message>
        <source>Every idle truck the FMS dispatches will be assigned automatically (empty: shortest shovel queue; loaded: shortest dump queue) until you switch it off.</source>
        <translation>Chaque camion libre réparti par le FMS sera affecté automatiquement (vide : file de pelle la plus courte ; chargé : file de déversement la plus courte) jusqu&apos;à ce que vous la désactiviez.</translation>
    </message>
    <message>
        <source>A&amp;uto dispatch ON</source>
        <translation>Répartition a&amp;uto ACTIVÉE</translation>
    </message>
    <message>
        <source>Auto dispatch ON — last: %1</source>
        <translation>Répartition automatique ACTIVÉE — dernière : %1</translation>
    </message>
    <message>
        <source>nothing yet</source>
        <translation>rien pour l&apos;instant</translation>
    </message>
    <message>
        <source>Auto dispatch OFF — last: %1</source>
        <translation>Répartition automatique DÉSACTIVÉE — dernière : %1</translation>
    </message>
    <message>
        <source>no areas yet (waiting for the road network)</source>
        <translation>pas encore de zones (attente du réseau routier)</translation>
    </message>
    <message>
        <source>no truck needs an assignment</source>
        <translation>aucun camion n&apos;a besoin d&apos;affectation</translation>
    </message>
    <message numerus="yes">
        <source>%n truck(s) need an assignment</source>
        <translation>
            <numerusform>%n camion a besoin d&apos;une affectation</numerusform>
            <numerusform>%n camions ont besoin d&apos;une affectation</numerusform>
        </translation>
    </message>
    <message>
        <source>No haul truck reports dispatch data yet.</source>
        <translation>Aucun tombereau ne signale encore de données de répartition.</translation>
    </message>
    <message>
        <source>no dispatch source</source>
        <translation>aucune source de répartition</translation>
    </message>
    <message>
        <source>Re-&amp;assign</source>
        <translation>Ré&amp;affecter</translation>
    </message>
    <message>
        <source>Send %1 to %2 as %3 (Ctrl+Enter)</source>
        <translation>Envoyer %1 vers %2 en %3 (Ctrl+Entrée)</translation>
    </message>
    <message>
        <source>preview: %1 → %2 · %3 m</source>
        <translation>aperçu : %1 → %2 · %3 m</translation>
    </message>
    <message>
        <source>Click an area on the 2D map for %1 (Esc cancels).</source>
        <translation>Cliquer une zone sur la carte 2D pour %1 (Échap annule).</translation>
    </message>
    <message>
        <source>That map area is not a destination of the road network (no area way %1).</source>
        <translation>Cette zone de la carte n&apos;est pas une destination du réseau routier (aucune voie de zone %1).</translation>
    </message>
    <message>
        <source>Destination picked on the map: %1</source>
        <translation>Destination choisie sur la carte : %1</translation>
    </message>
    <message>
        <source>%1 to %2 for %3</source>
        <translation>%1 vers %2 pour %3</translation>
    </message>
    <message>
        <source>Re-assign %1?</source>
        <translation>Réaffecter %1 ?</translation>
    </message>
    <message>
        <source>%1 has a %2 assignment (%3 to %4). Replace it with %5?</source>
        <translation>%1 a une affectation %2 (%3 vers %4). La remplacer par %5 ?</translation>
    </message>
    <message>
        <source>Assign %1</source>
        <translation>Affecter %1</translation>
    </message>
    <message>
        <source>Reset %1&apos;s assignment?</source>
        <translation>Réinitialiser l&apos;affectation de %1 ?</translation>
    </message>
    <message>
        <source>%1 will drop its %2 assignment (%3) and wait for a new one.</source>
        <translation>%1 abandonnera son affectation %2 (%3) et attendra une nouvelle.</translation>
    </message>
    <message>
        <source>current</source>
        <translation>actuelle</translation>
    </message>
    <message>
        <source>no task reported</source>
        <translation>aucune tâche signalée</translation>
    </message>
    <message>
        <source>Reset %1</source>
        <translation>Réinitialiser %1</translation>
    </message>
    <message>
        <source>%1: sent</source>
        <translation>%1 : envoyé</translation>
    </message>
    <message>
        <source>%1: NOT sent — %2</source>
        <translation>%1 : NON envoyé — %2</translation>
    </message>
    <message>
        <source>NOT sent — %1</source>
        <translation>NON envoyé — %1</translation>
    </message>
    <message>
        <source>the truck answered Accepted</source>
        <translation>le camion a répondu Accepted</translation>
    </message>
    <message>
        <source>the truck answered %1: %2</source>
        <translation>le camion a répondu %1 : %2</translation>
    </message>
    <message>
        <source>, assignment %1</source>
        <translation>, affectation %1</translation>
    </message>
</context>
<context>
    <name>ocu::DispatchQueueModel</name>
    <message>
        <source>at: %1</source>
        <translation>sur place : %1</translation>
    </message>
    <message>
        <source>coming: %1</source>
        <translation>en route : %1</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>voie %1</translation>
    </message>
    <message>
        <source>Shovel (load)</source>
        <translation>Pelle (chargement)</translation>
    </message>
    <message>
        <source>Dump (offload)</source>
        <translation>Déversement (déchargement)</translation>
    </message>
    <message>
        <source>Way %1 on %2. Coming: assigned (Pending/Active) and not yet there; at: the truck reports this area as its way (queued, spotting, loading or dumping).</source>
        <translation>Voie %1 sur %2. En route : affecté (Pending/Active) et pas encore arrivé ; sur place : le camion signale cette zone comme sa voie (en attente, en mise en place, en chargement ou en déversement).</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Coming</source>
        <translation>En route</translation>
    </message>
    <message>
        <source>At area</source>
        <translation>Sur place</translation>
    </message>
    <message>
        <source>Trucks</source>
        <translation>Camions</translation>
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
        <translation>Avertissement</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <source>Critical</source>
        <translation>Critique</translation>
    </message>
    <message>
        <source>link loss</source>
        <translation>perte de liaison</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>délai dépassé</translation>
    </message>
    <message>
        <source>health fault</source>
        <translation>défaut de santé</translation>
    </message>
    <message>
        <source>diagnostic</source>
        <translation>diagnostic</translation>
    </message>
    <message>
        <source>discrepancy</source>
        <translation>écart</translation>
    </message>
    <message>
        <source>control lost</source>
        <translation>contrôle perdu</translation>
    </message>
    <message>
        <source>text message</source>
        <translation>message texte</translation>
    </message>
    <message>
        <source>operator action</source>
        <translation>action opérateur</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>low</source>
        <translation>basse</translation>
    </message>
    <message>
        <source>medium</source>
        <translation>moyenne</translation>
    </message>
    <message>
        <source>high</source>
        <translation>haute</translation>
    </message>
    <message>
        <source>urgent</source>
        <translation>urgente</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>up</source>
        <translation>active</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>dégradée</translation>
    </message>
    <message>
        <source>down</source>
        <translation>coupée</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source>running</source>
        <translation>en marche</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>arrêté</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>avertissement</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>défaut</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>manuel</translation>
    </message>
    <message>
        <source>autonomous</source>
        <translation>autonome</translation>
    </message>
    <message>
        <source>remote</source>
        <translation>télécommandé</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>au repos</translation>
    </message>
    <message>
        <source>transition</source>
        <translation>transition</translation>
    </message>
    <message>
        <source>shutdown</source>
        <translation>éteint</translation>
    </message>
    <message>
        <source>monitoring</source>
        <translation>surveillance</translation>
    </message>
    <message>
        <source>this console</source>
        <translation>cette console</translation>
    </message>
    <message>
        <source>another console</source>
        <translation>autre console</translation>
    </message>
    <message>
        <source>denied</source>
        <translation>refusé</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>fault or stopped</source>
        <translation>défaut ou arrêté</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>périmé</translation>
    </message>
</context>
<context>
    <name>ocu::EventLogWidget</name>
    <message>
        <source>Unacknowledged</source>
        <translation>Non acquittés</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Acquitter</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation>Tout acquitter</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Exporter en CSV…</translation>
    </message>
    <message>
        <source>Search events…</source>
        <translation>Rechercher des événements…</translation>
    </message>
    <message>
        <source>All severities</source>
        <translation>Toutes les gravités</translation>
    </message>
    <message>
        <source>Warning and above</source>
        <translation>Avertissement et plus</translation>
    </message>
    <message>
        <source>Alarms only</source>
        <translation>Alarmes uniquement</translation>
    </message>
    <message>
        <source>Export events</source>
        <translation>Exporter les événements</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Fichiers CSV (*.csv)</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#d01010&apos;&gt;%1 unacknowledged&lt;/b&gt;</source>
        <translation>&lt;b style=&apos;color:#d01010&apos;&gt;%1 non acquitté(s)&lt;/b&gt;</translation>
    </message>
    <message>
        <source>no open alarms</source>
        <translation>aucune alarme ouverte</translation>
    </message>
    <message>
        <source>Shelved</source>
        <translation>En attente</translation>
    </message>
    <message>
        <source>Shelve</source>
        <translation>Mettre en attente</translation>
    </message>
    <message>
        <source>Unshelve</source>
        <translation>Reprendre</translation>
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
        <translation>8 h (poste)</translation>
    </message>
    <message>
        <source>Shelve the selected alarms: hidden and not annunciated until the time runs out</source>
        <translation>Mettre en attente les alarmes choisies : masquées et non annoncées jusqu&apos;à l&apos;échéance</translation>
    </message>
    <message>
        <source>Show shelved alarms too</source>
        <translation>Afficher aussi les alarmes en attente</translation>
    </message>
    <message>
        <source>New alarms in the last 10 minutes (EEMUA 191: more than 10 is a flood)</source>
        <translation>Nouvelles alarmes des 10 dernières minutes (EEMUA 191 : plus de 10 est une avalanche)</translation>
    </message>
    <message>
        <source>Select an alarm to see its details: the grouped machines, who acknowledged or shelved it, and when.</source>
        <translation>Choisir une alarme pour voir ses détails : les machines regroupées, qui l&apos;a acquittée ou mise en attente, et quand.</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#d01010&apos;&gt;ALARM FLOOD: %1 alarms / 10 min&lt;/b&gt;</source>
        <translation>&lt;b style=&apos;color:#d01010&apos;&gt;AVALANCHE D&apos;ALARMES : %1 alarmes / 10 min&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1 alarms / 10 min</source>
        <translation>%1 alarmes / 10 min</translation>
    </message>
    <message numerus="yes">
        <source>Priority: %1 · raised %2 · %n time(s)</source>
        <translation>
            <numerusform>Priorité : %1 · levée %2 · %n fois</numerusform>
            <numerusform>Priorité : %1 · levée %2 · %n fois</numerusform>
        </translation>
    </message>
    <message>
        <source>Acknowledged by %1 at %2</source>
        <translation>Acquittée par %1 à %2</translation>
    </message>
    <message>
        <source>Shelved by %1 until %2</source>
        <translation>Mise en attente par %1 jusqu&apos;à %2</translation>
    </message>
    <message>
        <source>Key: %1</source>
        <translation>Clé : %1</translation>
    </message>
    <message>
        <source>%1 items:</source>
        <translation>%1 éléments :</translation>
    </message>
</context>
<context>
    <name>ocu::FleetBridge</name>
    <message>
        <source>command &apos;%1&apos; not supported by %2</source>
        <translation>commande &apos;%1&apos; non prise en charge par %2</translation>
    </message>
    <message>
        <source>%1 io thread not turning</source>
        <translation>le thread d&apos;E/S de %1 ne tourne pas</translation>
    </message>
    <message>
        <source>%1 io thread has not turned for %2 s (watchdog): its links are degraded, data and commands are held up</source>
        <translation>le thread d&apos;E/S de %1 n&apos;a pas tourné depuis %2 s (chien de garde) : ses liaisons sont dégradées, données et commandes sont bloquées</translation>
    </message>
    <message>
        <source>%1 io thread turns again (watchdog)</source>
        <translation>le thread d&apos;E/S de %1 tourne à nouveau (chien de garde)</translation>
    </message>
</context>
<context>
    <name>ocu::FleetDiscrepancyAlarms</name>
    <message>
        <source>%1 autonomous machines of the FMS fleet are missing from the AHS fleet on %2</source>
        <translation>%1 machines autonomes de la flotte FMS manquent dans la flotte AHS sur %2</translation>
    </message>
    <message>
        <source>%1 machines are listed by both the FMS (manned) and the AHS on %2</source>
        <translation>%1 machines sont listées à la fois par le FMS (avec conducteur) et l&apos;AHS sur %2</translation>
    </message>
    <message>
        <source>%1 machines have a different HID at the AHS and the FMS on %2</source>
        <translation>%1 machines ont un HID différent dans l&apos;AHS et le FMS sur %2</translation>
    </message>
    <message>
        <source>%1 machines have a different type at the AHS and the FMS on %2</source>
        <translation>%1 machines ont un type différent dans l&apos;AHS et le FMS sur %2</translation>
    </message>
    <message>
        <source>%1 machines have different dimensions at the AHS and the FMS on %2</source>
        <translation>%1 machines ont des dimensions différentes dans l&apos;AHS et le FMS sur %2</translation>
    </message>
    <message>
        <source>%1 machines of the AHS are not in the FMS fleet on %2</source>
        <translation>%1 machines de l&apos;AHS ne sont pas dans la flotte FMS sur %2</translation>
    </message>
    <message>
        <source>Fleet definition discrepancy on %1: %2</source>
        <translation>Écart de définition de flotte sur %1 : %2</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… et %1 de plus</translation>
    </message>
</context>
<context>
    <name>ocu::FleetListWidget</name>
    <message>
        <source>Filter machines…</source>
        <translation>Filtrer les machines…</translation>
    </message>
    <message>
        <source>All protocols</source>
        <translation>Tous les protocoles</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Tous les états</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Avertissement</translation>
    </message>
    <message>
        <source>Fault / stopped</source>
        <translation>Défaut / arrêté</translation>
    </message>
    <message>
        <source>Stale / no comms</source>
        <translation>Périmé / sans communication</translation>
    </message>
    <message>
        <source>Autonomous</source>
        <translation>Autonome</translation>
    </message>
    <message>
        <source>Large rows</source>
        <translation>Grandes lignes</translation>
    </message>
    <message>
        <source>Switch between dense rows (workstation) and large rows (field laptop)</source>
        <translation>Basculer entre lignes compactes (poste de travail) et grandes lignes (portable de terrain)</translation>
    </message>
    <message>
        <source>Id: %1</source>
        <translation>ID : %1</translation>
    </message>
    <message>
        <source>Name: %1</source>
        <translation>Nom : %1</translation>
    </message>
    <message>
        <source>Type: %1</source>
        <translation>Type : %1</translation>
    </message>
    <message>
        <source>Protocol: %1</source>
        <translation>Protocole : %1</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>Liaison : %1</translation>
    </message>
    <message>
        <source>Position: E %1 m, N %2 m, U %3 m</source>
        <translation>Position : E %1 m, N %2 m, U %3 m</translation>
    </message>
    <message>
        <source>WGS84: %1, %2</source>
        <translation>WGS84 : %1, %2</translation>
    </message>
    <message>
        <source>Heading: %1°  Speed: %2 km/h</source>
        <translation>Cap : %1°  Vitesse : %2 km/h</translation>
    </message>
    <message>
        <source>Size: %1 × %2 × %3 m</source>
        <translation>Dimensions : %1 × %2 × %3 m</translation>
    </message>
    <message>
        <source>Mode: %1 (%2)</source>
        <translation>Mode : %1 (%2)</translation>
    </message>
    <message>
        <source>Stop (reported): %1 %2</source>
        <translation>Arrêt (signalé) : %1 %2</translation>
    </message>
    <message>
        <source>Controller: %1 (%2)</source>
        <translation>Contrôlé par : %1 (%2)</translation>
    </message>
    <message>
        <source>Health: %1 %2</source>
        <translation>Santé : %1 %2</translation>
    </message>
    <message>
        <source>Centre on map</source>
        <translation>Centrer sur la carte</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Stop %1 selected</source>
        <translation>Arrêter les %1 sélectionnées</translation>
    </message>
    <message>
        <source>Details…</source>
        <translation>Détails…</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Machine %1</translation>
    </message>
    <message>
        <source>Work: %1</source>
        <translation>Travail : %1</translation>
    </message>
</context>
<context>
    <name>ocu::FleetModel</name>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocole</translation>
    </message>
    <message>
        <source>Link / age</source>
        <translation>Liaison / âge</translation>
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
        <translation>Lat.</translation>
    </message>
    <message>
        <source>Lon</source>
        <translation>Long.</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Cap</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Mode / state</source>
        <translation>Mode / état</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêt</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Contrôlé par</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Santé</translation>
    </message>
    <message>
        <source>Last message</source>
        <translation>Dernier message</translation>
    </message>
    <message>
        <source>STOPPED</source>
        <translation>ARRÊTÉ</translation>
    </message>
    <message>
        <source>running</source>
        <translation>en marche</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source>this OCU</source>
        <translation>cette console</translation>
    </message>
    <message>
        <source>up</source>
        <translation>active</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>dégradée</translation>
    </message>
    <message>
        <source>down</source>
        <translation>coupée</translation>
    </message>
</context>
<context>
    <name>ocu::HandoffBanner</name>
    <message>
        <source>Accept</source>
        <translation>Accepter</translation>
    </message>
    <message>
        <source>Deny</source>
        <translation>Refuser</translation>
    </message>
    <message>
        <source>Ask for hand-off</source>
        <translation>Demander le transfert</translation>
    </message>
    <message>
        <source>Withdraw</source>
        <translation>Retirer</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Hand control of this vehicle to the console that asks</source>
        <translation>Céder le contrôle de ce véhicule à la console qui le demande</translation>
    </message>
    <message>
        <source>Keep control; the console that asks is told</source>
        <translation>Garder le contrôle ; la console qui le demande en est informée</translation>
    </message>
    <message>
        <source>Reason the holder&apos;s operator sees</source>
        <translation>Motif affiché à l&apos;opérateur du détenteur</translation>
    </message>
    <message>
        <source>Console %1 asks for control of %2 (authority %3).</source>
        <translation>La console %1 demande le contrôle de %2 (autorité %3).</translation>
    </message>
    <message>
        <source>Reason: %1</source>
        <translation>Motif : %1</translation>
    </message>
    <message numerus="yes">
        <source>%n more request(s) waiting after this one.</source>
        <translation>
            <numerusform>%n autre demande en attente après celle-ci.</numerusform>
            <numerusform>%n autres demandes en attente après celle-ci.</numerusform>
        </translation>
    </message>
    <message>
        <source>No time limit: the vehicle waits for your answer.</source>
        <translation>Pas de délai : le véhicule attend votre réponse.</translation>
    </message>
    <message numerus="yes">
        <source>Answer within %n s, else the vehicle refuses it (timeout).</source>
        <translation>
            <numerusform>Répondez sous %n s, sinon le véhicule refuse (délai dépassé).</numerusform>
            <numerusform>Répondez sous %n s, sinon le véhicule refuse (délai dépassé).</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is held by console %2 (authority %3). Ask its operator to hand it over:</source>
        <translation>%1 est contrôlé par la console %2 (autorité %3). Demander à son opérateur de le céder :</translation>
    </message>
    <message>
        <source>%1 is held by %2 (authority %3) and offers no Enhanced Access Control: asking takes control only with a higher authority than the holder&apos;s (ordinary pre-emption, authority %4 here).</source>
        <translation>%1 est contrôlé par %2 (autorité %3) et n&apos;offre pas le contrôle d&apos;accès étendu (Enhanced Access Control) : la demande ne prend le contrôle qu&apos;avec une autorité supérieure à celle du détenteur (préemption ordinaire, autorité %4 ici).</translation>
    </message>
    <message>
        <source>Waiting for the holder&apos;s answer</source>
        <translation>En attente de la réponse du détenteur</translation>
    </message>
    <message>
        <source>Granted: taking control</source>
        <translation>Accordé : prise de contrôle</translation>
    </message>
    <message>
        <source>Control handed over</source>
        <translation>Contrôle cédé</translation>
    </message>
    <message>
        <source>Denied</source>
        <translation>Refusé</translation>
    </message>
    <message>
        <source>No answer in time</source>
        <translation>Pas de réponse dans le délai</translation>
    </message>
    <message>
        <source>Refused</source>
        <translation>Rejeté</translation>
    </message>
    <message>
        <source>Withdrawn</source>
        <translation>Retiré</translation>
    </message>
    <message>
        <source>Requesting control (ordinary pre-emption)</source>
        <translation>Demande de contrôle (préemption ordinaire)</translation>
    </message>
    <message>
        <source>Hand-off of %1: %2.</source>
        <translation>Transfert de %1 : %2.</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>Attendre</translation>
    </message>
    <message>
        <source>Not yet: the request stays and the decision time starts again; the console that asks is told to wait</source>
        <translation>Pas encore : la demande reste et le délai de décision recommence ; la console qui demande est priée d’attendre</translation>
    </message>
    <message>
        <source>You asked it to wait; its console keeps the request up.</source>
        <translation>Vous lui avez demandé d’attendre ; sa console maintient la demande.</translation>
    </message>
    <message>
        <source>The holder asks you to wait; the request is kept up</source>
        <translation>Le détenteur vous demande d’attendre ; la demande est maintenue</translation>
    </message>
    <message>
        <source>%1 (console %2) asks for control of %3 (authority %4).</source>
        <translation>%1 (console %2) demande le contrôle de %3 (autorité %4).</translation>
    </message>
    <message>
        <source>%1 is held by %2 (console %3, authority %4). Ask them to hand it over:</source>
        <translation>%1 est contrôlé par %2 (console %3, autorité %4). Lui demander de le céder :</translation>
    </message>
</context>
<context>
    <name>ocu::HardwareStopButton</name>
    <message>
        <source>STOP button unavailable: the joystick subsystem did not start (%1)</source>
        <translation>Bouton STOP indisponible : le sous-système joystick n&apos;a pas démarré (%1)</translation>
    </message>
    <message>
        <source>button %1 of any joystick</source>
        <translation>bouton %1 de n&apos;importe quel joystick</translation>
    </message>
    <message>
        <source>button %1 of &quot;%2&quot;</source>
        <translation>bouton %1 de « %2 »</translation>
    </message>
    <message>
        <source>STOP button connected: %1 (%2)</source>
        <translation>Bouton STOP connecté : %1 (%2)</translation>
    </message>
    <message>
        <source>STOP button disconnected: %1; STOP ALL stays available on the console</source>
        <translation>Bouton STOP déconnecté : %1 ; ARRÊT GÉNÉRAL reste disponible sur la console</translation>
    </message>
</context>
<context>
    <name>ocu::HoldToConfirmButton</name>
    <message>
        <source>Press and hold to confirm</source>
        <translation>Maintenir appuyé pour confirmer</translation>
    </message>
</context>
<context>
    <name>ocu::IlluminationBar</name>
    <message>
        <source>Head</source>
        <translation>Phares</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Jour</translation>
    </message>
    <message>
        <source>◀ Turn</source>
        <translation>◀ Clign.</translation>
    </message>
    <message>
        <source>Turn ▶</source>
        <translation>Clign. ▶</translation>
    </message>
    <message>
        <source>Brake</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>IR</source>
        <translation>IR</translation>
    </message>
    <message>
        <source>Lights:</source>
        <translation>Feux :</translation>
    </message>
    <message>
        <source>Lights: not offered by this vehicle</source>
        <translation>Feux : non proposés par ce véhicule</translation>
    </message>
    <message>
        <source>%1: this vehicle has none</source>
        <translation>%1 : ce véhicule n&apos;en a pas</translation>
    </message>
    <message>
        <source>%1: not reported yet</source>
        <translation>%1 : pas encore signalé</translation>
    </message>
    <message>
        <source>%1: on, as the vehicle reports (click to switch off)</source>
        <translation>%1 : allumé selon le véhicule (cliquer pour éteindre)</translation>
    </message>
    <message>
        <source>%1: off, as the vehicle reports (click to switch on)</source>
        <translation>%1 : éteint selon le véhicule (cliquer pour allumer)</translation>
    </message>
</context>
<context>
    <name>ocu::ImageView</name>
    <message>
        <source>3D view unavailable</source>
        <translation>Vue 3D indisponible</translation>
    </message>
</context>
<context>
    <name>ocu::IsoBridge</name>
    <message>
        <source>connecting</source>
        <translation>connexion en cours</translation>
    </message>
    <message>
        <source>ISO 23725: a link could not start (see the event log)</source>
        <translation>ISO 23725 : une liaison n&apos;a pas pu démarrer (voir le journal des événements)</translation>
    </message>
    <message>
        <source>ISO 23725 link %1 down: %2</source>
        <translation>Liaison ISO 23725 %1 coupée : %2</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop %2%3</source>
        <translation>L&apos;AHS %1 signale l&apos;arrêt général %2%3</translation>
    </message>
    <message>
        <source> (issued by another system)</source>
        <translation> (émis par un autre système)</translation>
    </message>
    <message>
        <source>all-stop</source>
        <translation>arrêt général</translation>
    </message>
    <message>
        <source>no active diagnostics</source>
        <translation>aucun diagnostic actif</translation>
    </message>
    <message>
        <source>diagnostics %1</source>
        <translation>diagnostics %1</translation>
    </message>
    <message>
        <source>fuel %1 %</source>
        <translation>carburant %1 %</translation>
    </message>
    <message>
        <source>no ISO 23725 link configured</source>
        <translation>aucune liaison ISO 23725 configurée</translation>
    </message>
    <message>
        <source>%1: unknown ISO 23725 link &quot;%2&quot;</source>
        <translation>%1 : liaison ISO 23725 inconnue « %2 »</translation>
    </message>
    <message>
        <source>%1 on way %2</source>
        <translation>%1 sur la voie %2</translation>
    </message>
    <message>
        <source>payload %1 t</source>
        <translation>charge utile %1 t</translation>
    </message>
    <message>
        <source>loaded</source>
        <translation>chargé</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vide</translation>
    </message>
    <message>
        <source>body raised</source>
        <translation>benne levée</translation>
    </message>
    <message>
        <source>park brake on</source>
        <translation>frein de parc serré</translation>
    </message>
    <message>
        <source>assignment %1</source>
        <translation>affectation %1</translation>
    </message>
    <message>
        <source> (%1 at way %2)</source>
        <translation> (%1 à la voie %2)</translation>
    </message>
    <message>
        <source>last dump %1 t at way %2</source>
        <translation>dernier déversement %1 t à la voie %2</translation>
    </message>
    <message>
        <source>last dump at way %1</source>
        <translation>dernier déversement à la voie %1</translation>
    </message>
    <message>
        <source>ISO 23725 stack stopped</source>
        <translation>pile ISO 23725 arrêtée</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop active</source>
        <translation>l&apos;AHS %1 signale l&apos;arrêt général actif</translation>
    </message>
    <message>
        <source>AHS %1 reports all-stop inactive</source>
        <translation>l&apos;AHS %1 signale l&apos;arrêt général inactif</translation>
    </message>
    <message>
        <source>unknown ISO 23725 machine %1</source>
        <translation>machine ISO 23725 inconnue %1</translation>
    </message>
    <message>
        <source>assignment</source>
        <translation>affectation</translation>
    </message>
    <message>
        <source>assignment refused: %1 has not reported its DispatchingCustodian yet</source>
        <translation>affectation refusée : %1 n&apos;a pas encore signalé son DispatchingCustodian</translation>
    </message>
    <message>
        <source>assignment refused: %1 is dispatched by the %2 (DispatchingCustodian %2)</source>
        <translation>affectation refusée : %1 est réparti par le %2 (DispatchingCustodian %2)</translation>
    </message>
    <message>
        <source>implausible position ignored (%1 so far): %2</source>
        <translation>position invraisemblable ignorée (%1 jusqu&apos;ici) : %2</translation>
    </message>
    <message>
        <source>ISO 23725 link %1, machine %2: position ignored, %3 (lat %4, lon %5, speed %6 km/h); last good position kept (counted in rx.implausible.%7; one warning per machine and cause every 30 s)</source>
        <translation>liaison ISO 23725 %1, machine %2 : position ignorée, %3 (lat %4, lon %5, vitesse %6 km/h) ; dernière position valide conservée (comptée dans rx.implausible.%7 ; un avertissement par machine et par cause toutes les 30 s)</translation>
    </message>
    <message>
        <source>%1 refused: ISO 23725 link %2 is down%3; nothing sent</source>
        <translation>%1 refusé : la liaison ISO 23725 %2 est coupée%3 ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>%1 refused: ISO 23725 link %2 is not connected%3; nothing sent</source>
        <translation>%1 refusé : la liaison ISO 23725 %2 n&apos;est pas connectée%3 ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>all-stop Apply</source>
        <translation>arrêt général Apply</translation>
    </message>
    <message>
        <source>all-stop Remove</source>
        <translation>arrêt général Remove</translation>
    </message>
    <message>
        <source>the ISO 23725 stack is not running; nothing sent</source>
        <translation>la pile ISO 23725 ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>unknown ISO 23725 machine</source>
        <translation>machine ISO 23725 inconnue</translation>
    </message>
    <message>
        <source>%1: &quot;id&quot; must name an ISO 23725 machine</source>
        <translation>%1 : « id » doit désigner une machine ISO 23725</translation>
    </message>
    <message>
        <source>assign refused: %1; nothing sent</source>
        <translation>affectation refusée : %1 ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>no task given</source>
        <translation>aucune tâche indiquée</translation>
    </message>
</context>
<context>
    <name>ocu::IsoDispatchSource</name>
    <message>
        <source>the ISO 23725 bridge is gone</source>
        <translation>la passerelle ISO 23725 n&apos;existe plus</translation>
    </message>
    <message>
        <source>unknown truck</source>
        <translation>camion inconnu</translation>
    </message>
    <message>
        <source>no active assignment</source>
        <translation>aucune affectation active</translation>
    </message>
    <message>
        <source>the truck has not reported its way</source>
        <translation>le camion n&apos;a pas signalé sa voie</translation>
    </message>
    <message>
        <source>no MapConnectivityV1 from the AHS yet</source>
        <translation>pas encore de MapConnectivityV1 de l&apos;AHS</translation>
    </message>
    <message>
        <source>unknown truck or another AHS&apos;s area</source>
        <translation>camion inconnu ou zone d&apos;un autre AHS</translation>
    </message>
</context>
<context>
    <name>ocu::JausBridge</name>
    <message>
        <source>JAUS: %1</source>
        <translation>JAUS : %1</translation>
    </message>
    <message>
        <source>searching for subsystems</source>
        <translation>recherche de sous-systèmes</translation>
    </message>
    <message numerus="yes">
        <source>%n subsystem(s) up</source>
        <translation>
            <numerusform>%n sous-système actif</numerusform>
            <numerusform>%n sous-systèmes actifs</numerusform>
        </translation>
    </message>
    <message>
        <source>no subsystem answering</source>
        <translation>aucun sous-système ne répond</translation>
    </message>
    <message>
        <source>JAUS: no group socket (%1 held by another process)</source>
        <translation>JAUS : pas de socket de groupe (port %1 occupé par un autre processus)</translation>
    </message>
    <message>
        <source>JAUS: no group socket (%1)</source>
        <translation>JAUS : pas de socket de groupe (%1)</translation>
    </message>
    <message>
        <source>emergency</source>
        <translation>urgence</translation>
    </message>
    <message>
        <source>this console (%1)</source>
        <translation>cette console (%1)</translation>
    </message>
    <message>
        <source>%1 refused: this console&apos;s JAUS role is MONITOR</source>
        <translation>%1 : refusé, le rôle JAUS de cette console est MONITOR</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>clear emergency</source>
        <translation>levée de l&apos;urgence</translation>
    </message>
    <message>
        <source>drive</source>
        <translation>conduite</translation>
    </message>
    <message>
        <source>drive refused: this console does not control %1</source>
        <translation>conduite refusée : cette console ne contrôle pas %1</translation>
    </message>
    <message>
        <source>%1: &quot;id&quot; must name a JAUS machine such as &quot;jaus:101&quot;</source>
        <translation>%1 : &quot;id&quot; doit désigner une machine JAUS, p. ex. &quot;jaus:101&quot;</translation>
    </message>
    <message>
        <source>drive: &quot;duration&quot; must be between 0 and 60 seconds</source>
        <translation>drive : &quot;duration&quot; doit être compris entre 0 et 60 secondes</translation>
    </message>
    <message>
        <source>drive: effort must be within ±100 %</source>
        <translation>drive : l&apos;effort doit rester dans ±100 %</translation>
    </message>
    <message>
        <source>%1 reports EMERGENCY</source>
        <translation>%1 signale une URGENCE</translation>
    </message>
    <message>
        <source>%1 reports %2: emergency cleared</source>
        <translation>%1 signale %2 : urgence levée</translation>
    </message>
    <message>
        <source>no emergency</source>
        <translation>pas d&apos;urgence</translation>
    </message>
    <message>
        <source>%1 confirms control by this console</source>
        <translation>%1 confirme le contrôle par cette console</translation>
    </message>
    <message>
        <source>%1 refuses control: insufficient authority</source>
        <translation>%1 refuse le contrôle : autorité insuffisante</translation>
    </message>
    <message>
        <source>%1 reports control released</source>
        <translation>%1 signale le contrôle libéré</translation>
    </message>
    <message>
        <source>JAUS stack stopped</source>
        <translation>pile JAUS arrêtée</translation>
    </message>
    <message>
        <source>%1 refused: %2 has not been heard on the JAUS link; nothing sent</source>
        <translation>%1 refusé : %2 n&apos;a pas été entendu sur la liaison JAUS ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>%1 refused: the link to %2 is down; nothing sent</source>
        <translation>%1 refusé : la liaison avec %2 est coupée ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>the JAUS stack is not running; nothing sent</source>
        <translation>la pile JAUS ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>emergency stop refused by this console&apos;s JAUS role</source>
        <translation>arrêt d&apos;urgence refusé par le rôle JAUS de cette console</translation>
    </message>
    <message>
        <source>no JAUS vehicle known and the JAUS stack is not running; nothing sent</source>
        <translation>aucun véhicule JAUS connu et la pile JAUS ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>not a JAUS machine</source>
        <translation>pas une machine JAUS</translation>
    </message>
    <message>
        <source>clear emergency refused: this console&apos;s JAUS role has no command rights</source>
        <translation>levée d&apos;urgence refusée : le rôle JAUS de cette console n&apos;a pas de droits de commande</translation>
    </message>
    <message>
        <source>this console controls no JAUS vehicle: nothing to release</source>
        <translation>cette console ne contrôle aucun véhicule JAUS : rien à libérer</translation>
    </message>
    <message>
        <source>drive refused: the JAUS stack is not running; nothing sent</source>
        <translation>conduite refusée : la pile JAUS ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>drive refused: no drive session open for %1 (a session starts through the command gate)</source>
        <translation>conduite refusée : aucune session de conduite ouverte pour %1 (une session démarre par le contrôleur de commandes)</translation>
    </message>
    <message>
        <source>drive demand handed to the drive stream</source>
        <translation>consigne de conduite transmise au flux de conduite</translation>
    </message>
    <message>
        <source>the JAUS stack is not running; no zero drive commands sent</source>
        <translation>la pile JAUS ne tourne pas ; aucune commande de conduite nulle envoyée</translation>
    </message>
    <message>
        <source>zero drive commands handed to the stack</source>
        <translation>commandes de conduite nulles transmises à la pile</translation>
    </message>
    <message>
        <source>pan-tilt</source>
        <translation>orientation caméra</translation>
    </message>
    <message>
        <source>pan-tilt refused: the JAUS stack is not running; nothing sent</source>
        <translation>orientation caméra refusée : la pile JAUS ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>pan-tilt refused: this console does not control %1</source>
        <translation>orientation caméra refusée : cette console ne contrôle pas %1</translation>
    </message>
    <message>
        <source>pan-tilt refused: the rates must be finite numbers</source>
        <translation>orientation caméra refusée : les vitesses doivent être des nombres finis</translation>
    </message>
    <message>
        <source>pan-tilt demand handed to the stack</source>
        <translation>consigne d&apos;orientation caméra transmise à la pile</translation>
    </message>
    <message>
        <source>implausible pose ignored (%1 so far): %2</source>
        <translation>pose invraisemblable ignorée (%1 jusqu&apos;ici) : %2</translation>
    </message>
    <message>
        <source>JAUS subsystem %1: pose ignored, %2 (east %3 m, north %4 m, speed %5 m/s); last good pose kept (counted in rx.implausible.%6; one warning per vehicle and cause every 30 s)</source>
        <translation>sous-système JAUS %1 : pose ignorée, %2 (est %3 m, nord %4 m, vitesse %5 m/s) ; dernière pose valide conservée (comptée dans rx.implausible.%6 ; un avertissement par véhicule et par cause toutes les 30 s)</translation>
    </message>
    <message>
        <source>%1 reports the mission %2</source>
        <translation>%1 signale la mission %2</translation>
    </message>
    <message>
        <source>last reported: odometer %1 m, trip %2 m</source>
        <translation>dernier relevé : odomètre %1 m, trajet %2 m</translation>
    </message>
    <message>
        <source>drive refused: %1 reports the emergency platform state; nothing sent</source>
        <translation>conduite refusée : %1 signale l&apos;état d&apos;urgence de la plateforme ; rien n&apos;est envoyé</translation>
    </message>
</context>
<context>
    <name>ocu::JausControlPanel</name>
    <message>
        <source>Release all</source>
        <translation>Tout libérer</translation>
    </message>
    <message>
        <source>This console: %1 [%2] · authority %3</source>
        <translation>Cette console : %1 [%2] · autorité %3</translation>
    </message>
    <message>
        <source>This console: %1 [%2] · MONITOR role: commands are disabled</source>
        <translation>Cette console : %1 [%2] · rôle MONITOR : commandes désactivées</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Surveiller</translation>
    </message>
    <message>
        <source>Select this vehicle to watch it (no control)</source>
        <translation>Sélectionner ce véhicule pour le surveiller (sans contrôle)</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>Contrôler</translation>
    </message>
    <message>
        <source>Request control with this console&apos;s authority</source>
        <translation>Demander le contrôle avec l&apos;autorité de cette console</translation>
    </message>
    <message>
        <source>Release</source>
        <translation>Libérer</translation>
    </message>
    <message>
        <source>Release control of this vehicle</source>
        <translation>Libérer le contrôle de ce véhicule</translation>
    </message>
    <message>
        <source>No machine selected.
Select one in the fleet list, in the table above or on the map (click, or Tab to the list and use the arrow keys) to see its details here.</source>
        <translation>Aucune machine sélectionnée.
En sélectionner une dans la liste de la flotte, dans le tableau ci-dessus ou sur la carte (clic, ou Tab jusqu&apos;à la liste puis les flèches) pour voir ses détails ici.</translation>
    </message>
</context>
<context>
    <name>ocu::JausPlatform</name>
    <message>
        <source>standard</source>
        <translation>standard</translation>
    </message>
    <message>
        <source>training</source>
        <translation>entraînement</translation>
    </message>
    <message>
        <source>maintenance</source>
        <translation>maintenance</translation>
    </message>
    <message>
        <source>program mode %1</source>
        <translation>mode programme %1</translation>
    </message>
    <message>
        <source>initialize</source>
        <translation>initialisation</translation>
    </message>
    <message>
        <source>operational</source>
        <translation>opérationnel</translation>
    </message>
    <message>
        <source>shutdown</source>
        <translation>arrêt</translation>
    </message>
    <message>
        <source>system abort</source>
        <translation>abandon système</translation>
    </message>
    <message>
        <source>emergency</source>
        <translation>urgence</translation>
    </message>
    <message>
        <source>render useless</source>
        <translation>mise hors d&apos;usage</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>état %1</translation>
    </message>
    <message>
        <source>headlights</source>
        <translation>phares</translation>
    </message>
    <message>
        <source>left turn signal</source>
        <translation>clignotant gauche</translation>
    </message>
    <message>
        <source>right turn signal</source>
        <translation>clignotant droit</translation>
    </message>
    <message>
        <source>running lights</source>
        <translation>feux de jour</translation>
    </message>
    <message>
        <source>brake lights</source>
        <translation>feux stop</translation>
    </message>
    <message>
        <source>IR source</source>
        <translation>source IR</translation>
    </message>
</context>
<context>
    <name>ocu::JausSubsystemModel</name>
    <message>
        <source>unnamed</source>
        <translation>sans nom</translation>
    </message>
    <message>
        <source>%1 · %2 s</source>
        <translation>%1 · %2 s</translation>
    </message>
    <message>
        <source>this console (%1)</source>
        <translation>cette console (%1)</translation>
    </message>
    <message>
        <source>%1.%2.%3 (%4)</source>
        <translation>%1.%2.%3 (%4)</translation>
    </message>
    <message>
        <source>nobody</source>
        <translation>personne</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source> · EMERGENCY</source>
        <translation> · EMERGENCY</translation>
    </message>
    <message>
        <source>Vehicle [ID]</source>
        <translation>Véhicule [ID]</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Liaison</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Accès</translation>
    </message>
    <message>
        <source>Controlled by</source>
        <translation>Contrôlé par</translation>
    </message>
    <message>
        <source>Management</source>
        <translation>Gestion</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Santé</translation>
    </message>
    <message>
        <source>Actions</source>
        <translation>Actions</translation>
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
        <translation>orientation caméra : cette liaison véhicule ne pilote aucune tourelle ; rien n&apos;a été envoyé</translation>
    </message>
</context>
<context>
    <name>ocu::JoystickMappingDialog</name>
    <message>
        <source>Invert</source>
        <translation>Inverser</translation>
    </message>
    <message>
        <source>Joystick mapping</source>
        <translation>Affectation du joystick</translation>
    </message>
    <message>
        <source>Detect…</source>
        <translation>Détecter…</translation>
    </message>
    <message>
        <source>Then push the stick fully forward</source>
        <translation>Puis poussez le manche à fond vers l’avant</translation>
    </message>
    <message>
        <source>Then push the stick fully right</source>
        <translation>Puis poussez le manche à fond vers la droite</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Périphérique</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>Forward / reverse</source>
        <translation>Avant / arrière</translation>
    </message>
    <message>
        <source>Turn</source>
        <translation>Virage</translation>
    </message>
    <message>
        <source>Dead zone</source>
        <translation>Zone morte</translation>
    </message>
    <message>
        <source>Move the stick to see its axes.</source>
        <translation>Bougez le manche pour voir ses axes.</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Axe %1</translation>
    </message>
    <message>
        <source>Push the stick fully forward and hold it…</source>
        <translation>Poussez le manche à fond vers l’avant et maintenez-le…</translation>
    </message>
    <message>
        <source>Push the stick fully to the right and hold it…</source>
        <translation>Poussez le manche à fond vers la droite et maintenez-le…</translation>
    </message>
    <message>
        <source>%1: axis %2%3 — release the stick.</source>
        <translation>%1 : axe %2%3 – relâchez le manche.</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Avant</translation>
    </message>
    <message>
        <source>, inverted</source>
        <translation>, inversé</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Demand: forward %1 %, turn %2 %</source>
        <translation>Consigne : avant %1 %, virage %2 %</translation>
    </message>
    <message>
        <source>Forward and turn need two different axes.</source>
        <translation>L’avant et le virage exigent deux axes différents.</translation>
    </message>
</context>
<context>
    <name>ocu::LegendOverlay</name>
    <message>
        <source>Passes</source>
        <translation>Passes</translation>
    </message>
</context>
<context>
    <name>ocu::LinkIndicator</name>
    <message>
        <source>off</source>
        <translation>désactivée</translation>
    </message>
    <message>
        <source>up</source>
        <translation>active</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>dégradée</translation>
    </message>
    <message>
        <source>down</source>
        <translation>coupée</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1: no input rejected</source>
        <translation>%1 : aucune entrée rejetée</translation>
    </message>
    <message>
        <source>%1: %2 inputs rejected</source>
        <translation>%1 : %2 entrées rejetées</translation>
    </message>
</context>
<context>
    <name>ocu::LockScreen</name>
    <message>
        <source>Console locked</source>
        <translation>Console verrouillée</translation>
    </message>
    <message>
        <source>The picture is read-only. STOP ALL stays active (F12).</source>
        <translation>L&apos;affichage est en lecture seule. ARRÊT GÉNÉRAL reste actif (F12).</translation>
    </message>
    <message>
        <source>&amp;Unlock…</source>
        <translation>&amp;Déverrouiller…</translation>
    </message>
    <message>
        <source>S&amp;witch operator…</source>
        <translation>&amp;Changer d&apos;opérateur…</translation>
    </message>
</context>
<context>
    <name>ocu::MainWindow</name>
    <message>
        <source>Operator Control Unit</source>
        <translation>Poste de commande opérateur</translation>
    </message>
    <message>
        <source>Fleet</source>
        <translation>Flotte</translation>
    </message>
    <message>
        <source>Site map (2D)</source>
        <translation>Plan du site (2D)</translation>
    </message>
    <message>
        <source>Site 3D</source>
        <translation>Site 3D</translation>
    </message>
    <message>
        <source>JAUS control</source>
        <translation>Contrôle JAUS</translation>
    </message>
    <message>
        <source>Teleop</source>
        <translation>Téléopération</translation>
    </message>
    <message>
        <source>Pass counts</source>
        <translation>Nombre de passes</translation>
    </message>
    <message>
        <source>Event log</source>
        <translation>Journal des événements</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Démarrage…</translation>
    </message>
    <message>
        <source>Safety</source>
        <translation>Sécurité</translation>
    </message>
    <message>
        <source>STOP ALL</source>
        <translation>ARRÊT GÉNÉRAL</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Save &amp;screenshot…</source>
        <translation>Enregistrer une &amp;capture d&apos;écran…</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Enregistrer une capture d&apos;écran</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Images PNG (*.png)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Night palette</source>
        <translation>Palette de &amp;nuit</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Aid&amp;e</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Raccourcis clavier</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>À &amp;propos</translation>
    </message>
    <message>
        <source>About the Operator Control Unit</source>
        <translation>À propos du poste de commande opérateur</translation>
    </message>
    <message>
        <source>No unacknowledged alarms</source>
        <translation>Aucune alarme non acquittée</translation>
    </message>
    <message numerus="yes">
        <source>%n unacknowledged alarm(s)</source>
        <translation>
            <numerusform>%n alarme non acquittée</numerusform>
            <numerusform>%n alarmes non acquittées</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 and %2</source>
        <translation>%1 et %2</translation>
    </message>
    <message>
        <source>Stop failure</source>
        <translation>Échec d&apos;arrêt</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Masquer</translation>
    </message>
    <message>
        <source>Hide this warning. It does not change what the machines do.</source>
        <translation>Masquer cet avertissement. Cela ne change rien à ce que font les machines.</translation>
    </message>
    <message>
        <source>&amp;Reset workspace</source>
        <translation>&amp;Réinitialiser l&apos;espace de travail</translation>
    </message>
    <message>
        <source>&amp;Go to panel</source>
        <translation>&amp;Aller au panneau</translation>
    </message>
    <message>
        <source>Operator Control Unit %1
%2 on one console.</source>
        <translation>Poste de commande opérateur %1
%2 sur une seule console.</translation>
    </message>
    <message>
        <source>Stop every machine this console can reach</source>
        <translation>Arrêter toutes les machines que cette console peut atteindre</translation>
    </message>
    <message>
        <source>Stop every machine this console can reach: %1</source>
        <translation>Arrêter toutes les machines que cette console peut atteindre : %1</translation>
    </message>
    <message>
        <source>%1 (F12 or Ctrl+Shift+Space). Stopping never asks for confirmation; a stop that does not reach everything shows a red banner.</source>
        <translation>%1 (F12 ou Ctrl+Maj+Espace). L&apos;arrêt ne demande jamais de confirmation ; un arrêt qui n&apos;atteint pas tout affiche un bandeau rouge.</translation>
    </message>
    <message>
        <source>F12 or Ctrl+Shift+Space: STOP ALL</source>
        <translation>F12 ou Ctrl+Maj+Espace : ARRÊT GÉNÉRAL</translation>
    </message>
    <message>
        <source>Site map: arrows pan, +/- or wheel zoom (about the cursor), F follow the selected machine, Home whole site, Shift+Home the fleet, S the selection, A the area under the cursor, C centre; double-click selects; click an edge arrow to go to machines outside the view</source>
        <translation>Plan du site : flèches pour déplacer, +/- ou molette pour zoomer (autour du curseur), F suivre la machine sélectionnée, Origine tout le site, Maj+Origine la flotte, S la sélection, A la zone sous le curseur, C centrer ; double clic pour sélectionner ; cliquer une flèche de bord pour aller aux machines hors de la vue</translation>
    </message>
    <message>
        <source>Ctrl+Shift+N: night palette</source>
        <translation>Ctrl+Maj+N : palette de nuit</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P: save a screenshot</source>
        <translation>Ctrl+Maj+P : enregistrer une capture d&apos;écran</translation>
    </message>
    <message>
        <source>Workspaces (View › Reset workspace puts the current one back as it was):</source>
        <translation>Espaces de travail (Affichage › Réinitialiser l&apos;espace de travail rétablit l&apos;espace courant tel qu&apos;il était) :</translation>
    </message>
    <message>
        <source>Go to a panel (raises it and puts the keyboard focus in it):</source>
        <translation>Aller à un panneau (le met au premier plan et y place le focus clavier) :</translation>
    </message>
    <message>
        <source>Tab / Shift+Tab: next / previous control in a panel; arrows move in lists and tables; Space or Enter presses the focused button</source>
        <translation>Tab / Maj+Tab : contrôle suivant / précédent d&apos;un panneau ; les flèches se déplacent dans les listes et tableaux ; Espace ou Entrée appuie sur le bouton actif</translation>
    </message>
    <message>
        <source>See docs/keyboard.md for the full list.</source>
        <translation>Voir docs/keyboard.md pour la liste complète.</translation>
    </message>
    <message>
        <source>%1 STOP ALL did NOT reach: %2</source>
        <translation>%1 ARRÊT GÉNÉRAL n&apos;a PAS atteint : %2</translation>
    </message>
    <message>
        <source>%1 STOP did NOT reach: %2</source>
        <translation>%1 ARRÊT n&apos;a PAS atteint : %2</translation>
    </message>
    <message>
        <source>Dispatch</source>
        <translation>Répartition</translation>
    </message>
    <message>
        <source>Dispatch: F6 next truck needing work, Alt+T task, Alt+D destination, Alt+M pick on map, Ctrl+Enter assign, Alt+R reset</source>
        <translation>Répartition : F6 camion suivant sans travail, Alt+T tâche, Alt+D destination, Alt+C choisir sur la carte, Ctrl+Entrée affecter, Alt+R réinitialiser</translation>
    </message>
    <message>
        <source>Production</source>
        <translation>Production</translation>
    </message>
    <message>
        <source>ISO 23725 all-stop to every AHS link</source>
        <translation>arrêt général ISO 23725 vers chaque liaison AHS</translation>
    </message>
    <message>
        <source>Teleop panel: W/A/S/D or arrows with the dead-man key held; Space or Esc: emergency stop</source>
        <translation>Panneau de téléopération : W/A/S/D ou flèches avec la touche homme mort maintenue ; Espace ou Échap : arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>Mission</source>
        <translation>Mission</translation>
    </message>
    <message>
        <source>Mission panel (Ctrl+U): Alt+E edit on the map, Alt+O open, Alt+I import GPX/KML, Alt+S save, Alt+L upload, Alt+P pause, Alt+B abort. Editing on the map: click adds a waypoint, drag moves it, click a leg inserts one; Insert or Enter adds at the cursor, Delete removes the selected one, Page Up/Down select, Shift+arrows move it, Ctrl+Z / Ctrl+Shift+Z undo / redo, Esc ends editing; right-click on the ground: Go here</source>
        <translation>Panneau Mission (Ctrl+U) : Alt+S modifier sur la carte, Alt+O ouvrir, Alt+I importer GPX/KML, Alt+E enregistrer, Alt+V envoyer, Alt+P pause, Alt+B abandonner. Édition sur la carte : un clic ajoute un point de passage, le glisser le déplace, un clic sur un tronçon en insère un ; Inser ou Entrée ajoute au curseur, Suppr supprime le point sélectionné, Page préc./suiv. sélectionnent, Maj+flèches le déplacent, Ctrl+Z / Ctrl+Maj+Z annuler / rétablir, Échap termine l&apos;édition ; clic droit sur le sol : Aller ici</translation>
    </message>
    <message>
        <source>JAUS emergency stop to every discovered vehicle</source>
        <translation>arrêt d&apos;urgence JAUS vers chaque véhicule découvert</translation>
    </message>
    <message>
        <source>the OSYRIS stop message</source>
        <translation>le message d&apos;arrêt OSYRIS</translation>
    </message>
    <message>
        <source>Video</source>
        <translation>Vidéo</translation>
    </message>
    <message>
        <source>Video panel (Ctrl+I): camera, full screen (Esc returns), resume driving</source>
        <translation>Panneau Vidéo (Ctrl+I) : caméra, plein écran (Échap pour revenir), reprendre la conduite</translation>
    </message>
    <message>
        <source>Control room</source>
        <translation>Salle de contrôle</translation>
    </message>
</context>
<context>
    <name>ocu::MissionGeoJson</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>pas du JSON (%1 à l&apos;octet %2)</translation>
    </message>
    <message>
        <source>no GeoJSON LineString (the route) in it</source>
        <translation>aucun LineString GeoJSON (l&apos;itinéraire) dedans</translation>
    </message>
    <message>
        <source>the route has no positions</source>
        <translation>l&apos;itinéraire n&apos;a aucune position</translation>
    </message>
    <message>
        <source>properties.waypoints must list one {speed, tolerance} per position (%1 positions)</source>
        <translation>properties.waypoints doit lister un {speed, tolerance} par position (%1 positions)</translation>
    </message>
    <message>
        <source>position %1 is not [longitude, latitude]</source>
        <translation>la position %1 n&apos;est pas [longitude, latitude]</translation>
    </message>
    <message>
        <source>position %1 lies outside WGS84 (latitude %2, longitude %3)</source>
        <translation>la position %1 est hors WGS84 (latitude %2, longitude %3)</translation>
    </message>
    <message>
        <source>waypoint %1: speed must be a number of 0 or more, tolerance 0 to 100 m</source>
        <translation>point de passage %1 : la vitesse doit être un nombre supérieur ou égal à 0, la tolérance de 0 à 100 m</translation>
    </message>
    <message>
        <source>cannot be opened (%1)</source>
        <translation>ne peut pas être ouvert (%1)</translation>
    </message>
    <message>
        <source>too large for a mission file</source>
        <translation>trop volumineux pour un fichier de mission</translation>
    </message>
    <message>
        <source>the plan has no waypoints to save</source>
        <translation>le plan n&apos;a aucun point de passage à enregistrer</translation>
    </message>
    <message>
        <source>cannot be written (%1)</source>
        <translation>ne peut pas être écrit (%1)</translation>
    </message>
</context>
<context>
    <name>ocu::MissionImport</name>
    <message>
        <source>no such readable file</source>
        <translation>aucun fichier lisible de ce nom</translation>
    </message>
    <message>
        <source>not a route GDAL can read (%1)</source>
        <translation>pas un itinéraire lisible par GDAL (%1)</translation>
    </message>
    <message>
        <source>unknown format</source>
        <translation>format inconnu</translation>
    </message>
    <message>
        <source>has no route, track or points</source>
        <translation>ne contient ni itinéraire, ni trace, ni points</translation>
    </message>
    <message>
        <source>has points outside WGS84</source>
        <translation>contient des points hors WGS84</translation>
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
        <translation>1 point de passage</translation>
    </message>
    <message>
        <source>%1 waypoints</source>
        <translation>%1 points de passage</translation>
    </message>
    <message>
        <source>Sending missions is not available in this build: the plan can be edited, saved, opened and drawn.</source>
        <translation>L&apos;envoi de missions n&apos;est pas disponible dans cette version : le plan peut être modifié, enregistré, ouvert et affiché.</translation>
    </message>
    <message>
        <source>&amp;Edit on map</source>
        <translation>Modifier &amp;sur la carte</translation>
    </message>
    <message>
        <source>Click on the map to add waypoints, drag them, click a leg to insert one</source>
        <translation>Cliquer sur la carte pour ajouter des points de passage, les faire glisser, cliquer sur un tronçon pour en insérer un</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>Open a mission saved as GeoJSON</source>
        <translation>Ouvrir une mission enregistrée en GeoJSON</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importer…</translation>
    </message>
    <message>
        <source>Import a route from GPX or KML</source>
        <translation>Importer un itinéraire GPX ou KML</translation>
    </message>
    <message>
        <source>&amp;Save…</source>
        <translation>&amp;Enregistrer…</translation>
    </message>
    <message>
        <source>Save the plan as GeoJSON</source>
        <translation>Enregistrer le plan en GeoJSON</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vider</translation>
    </message>
    <message>
        <source>Remove every waypoint (undo brings them back)</source>
        <translation>Supprimer tous les points de passage (Annuler les rétablit)</translation>
    </message>
    <message>
        <source>Delete waypoint</source>
        <translation>Supprimer le point</translation>
    </message>
    <message>
        <source>Delete the selected waypoint (Delete)</source>
        <translation>Supprimer le point de passage sélectionné (Suppr)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Undo the last edit (Ctrl+Z)</source>
        <translation>Annuler la dernière modification (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rétablir</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Rétablir (Ctrl+Maj+Z)</translation>
    </message>
    <message>
        <source>Up&amp;load</source>
        <translation>En&amp;voyer</translation>
    </message>
    <message>
        <source>Send the plan to the vehicle; uploaded once read back equal</source>
        <translation>Envoyer le plan au véhicule ; considéré envoyé une fois relu à l&apos;identique</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Démarrer</translation>
    </message>
    <message>
        <source>Run the uploaded mission from the waypoint chosen beside</source>
        <translation>Exécuter la mission envoyée à partir du point de passage choisi à côté</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Pause the running mission</source>
        <translation>Mettre en pause la mission en cours</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reprendre</translation>
    </message>
    <message>
        <source>Resume the paused mission</source>
        <translation>Reprendre la mission en pause</translation>
    </message>
    <message>
        <source>A&amp;bort</source>
        <translation>A&amp;bandonner</translation>
    </message>
    <message>
        <source>Abort the mission</source>
        <translation>Abandonner la mission</translation>
    </message>
    <message>
        <source>from </source>
        <translation>depuis </translation>
    </message>
    <message>
        <source>The waypoint the mission starts from</source>
        <translation>Le point de passage d&apos;où part la mission</translation>
    </message>
    <message>
        <source>Clear plan</source>
        <translation>Vider le plan</translation>
    </message>
    <message>
        <source>Sent to the command gate: the event log shows what went on the wire, the state above what the vehicle reports</source>
        <translation>Envoyé au contrôleur de commandes : le journal des événements montre ce qui a été émis, l&apos;état ci-dessus ce que signale le véhicule</translation>
    </message>
    <message>
        <source>UGV %1</source>
        <translation>UGV %1</translation>
    </message>
    <message>
        <source>Mission of %1 (%2)</source>
        <translation>Mission de %1 (%2)</translation>
    </message>
    <message>
        <source>Select a UGV on the map or in the fleet list to plan its mission.</source>
        <translation>Sélectionner un UGV sur la carte ou dans la liste de la flotte pour planifier sa mission.</translation>
    </message>
    <message>
        <source>%1: %2, %3</source>
        <translation>%1 : %2, %3</translation>
    </message>
    <message>
        <source>No waypoints yet: Edit on map, then click on the map to add them.</source>
        <translation>Aucun point de passage : Modifier sur la carte, puis cliquer sur la carte pour les ajouter.</translation>
    </message>
    <message>
        <source>%1, %2, ETA %3</source>
        <translation>%1, %2, arrivée %3</translation>
    </message>
    <message>
        <source>; from the vehicle %1, %2</source>
        <translation> ; du véhicule %1, %2</translation>
    </message>
    <message>
        <source>Planned: %1, not uploaded</source>
        <translation>Planifiée : %1, non envoyée</translation>
    </message>
    <message>
        <source>No mission</source>
        <translation>Aucune mission</translation>
    </message>
    <message>
        <source>Uploading %1…</source>
        <translation>Envoi de %1…</translation>
    </message>
    <message>
        <source>Uploaded and verified: %1</source>
        <translation>Envoyée et vérifiée : %1</translation>
    </message>
    <message>
        <source>Running: waypoint %1 of %2</source>
        <translation>En cours : point %1 sur %2</translation>
    </message>
    <message>
        <source>, %1 to go</source>
        <translation>, encore %1</translation>
    </message>
    <message>
        <source>, ETA %1</source>
        <translation>, arrivée %1</translation>
    </message>
    <message>
        <source>Paused at waypoint %1 of %2</source>
        <translation>En pause au point %1 sur %2</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>En pause</translation>
    </message>
    <message>
        <source>Completed: %1</source>
        <translation>Terminée : %1</translation>
    </message>
    <message>
        <source>Aborted at waypoint %1 of %2</source>
        <translation>Abandonnée au point %1 sur %2</translation>
    </message>
    <message>
        <source>Aborted</source>
        <translation>Abandonnée</translation>
    </message>
    <message>
        <source>Stopped by emergency at waypoint %1 of %2</source>
        <translation>Arrêtée par l&apos;urgence au point %1 sur %2</translation>
    </message>
    <message>
        <source>Stopped by emergency</source>
        <translation>Arrêtée par l&apos;urgence</translation>
    </message>
    <message>
        <source>; clearing the emergency does not restart it</source>
        <translation> ; lever l&apos;urgence ne la relance pas</translation>
    </message>
    <message>
        <source>Unknown, last seen at waypoint %1 of %2</source>
        <translation>Inconnu, vue pour la dernière fois au point %1 sur %2</translation>
    </message>
    <message>
        <source>Unknown: not seen running</source>
        <translation>Inconnu : jamais vue en cours</translation>
    </message>
    <message>
        <source>Rejected: %1</source>
        <translation>Refusée : %1</translation>
    </message>
    <message>
        <source>no reason given</source>
        <translation>aucune raison donnée</translation>
    </message>
    <message>
        <source> (%1)</source>
        <translation> (%1)</translation>
    </message>
    <message>
        <source>; not ours: another console holds the vehicle&apos;s list driver</source>
        <translation> ; pas la nôtre : une autre console détient le List Driver du véhicule</translation>
    </message>
    <message>
        <source>; the plan differs from the uploaded mission</source>
        <translation> ; le plan diffère de la mission envoyée</translation>
    </message>
    <message>
        <source>; driven path from the %1</source>
        <translation> ; trajet parcouru d&apos;après : %1</translation>
    </message>
    <message>
        <source>Go here sent to the command gate for %1: the event log shows what went on the wire</source>
        <translation>Aller ici pour %1 envoyé au contrôleur de commandes : le journal des événements montre ce qui a été émis</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Ouvrir %1</translation>
    </message>
    <message>
        <source>Opened %1: %2</source>
        <translation>%1 ouvert : %2</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message>
        <source>Imported %1: %2 with the vehicle&apos;s default speed and tolerance</source>
        <translation>%1 importé : %2 avec la vitesse et la tolérance par défaut du véhicule</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <source>Mission (*.geojson *.json)</source>
        <translation>Mission (*.geojson *.json)</translation>
    </message>
    <message>
        <source>Save mission</source>
        <translation>Enregistrer la mission</translation>
    </message>
    <message>
        <source>Open mission</source>
        <translation>Ouvrir une mission</translation>
    </message>
    <message>
        <source>Import route</source>
        <translation>Importer un itinéraire</translation>
    </message>
    <message>
        <source>Routes (*.gpx *.kml);;All files (*)</source>
        <translation>Itinéraires (*.gpx *.kml);;Tous les fichiers (*)</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlan</name>
    <message>
        <source>Add waypoint %1</source>
        <translation>Ajouter le point %1</translation>
    </message>
    <message>
        <source>Insert waypoint %1</source>
        <translation>Insérer le point %1</translation>
    </message>
    <message>
        <source>Move waypoint %1</source>
        <translation>Déplacer le point %1</translation>
    </message>
    <message>
        <source>Delete waypoint %1</source>
        <translation>Supprimer le point %1</translation>
    </message>
    <message>
        <source>Speed of waypoint %1</source>
        <translation>Vitesse du point %1</translation>
    </message>
    <message>
        <source>Tolerance of waypoint %1</source>
        <translation>Tolérance du point %1</translation>
    </message>
    <message>
        <source>Default speeds and tolerances</source>
        <translation>Vitesses et tolérances par défaut</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlanEditor</name>
    <message>
        <source>Go here (%1)</source>
        <translation>Aller ici (%1)</translation>
    </message>
    <message>
        <source>Delete waypoint %1</source>
        <translation>Supprimer le point %1</translation>
    </message>
    <message>
        <source>Insert waypoint between %1 and %2</source>
        <translation>Insérer un point entre %1 et %2</translation>
    </message>
    <message>
        <source>Add waypoint here</source>
        <translation>Ajouter un point ici</translation>
    </message>
</context>
<context>
    <name>ocu::MissionPlanTableModel</name>
    <message>
        <source>vehicle</source>
        <translation>véhicule</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Latitude</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Longitude</translation>
    </message>
    <message>
        <source>Speed m/s</source>
        <translation>Vitesse m/s</translation>
    </message>
    <message>
        <source>Tolerance m</source>
        <translation>Tolérance m</translation>
    </message>
</context>
<context>
    <name>ocu::MissionTakeover</name>
    <message>
        <source>the mission was not paused: %1</source>
        <translation>la mission n&apos;a pas été mise en pause : %1</translation>
    </message>
    <message>
        <source>a takeover of the mission is already being confirmed</source>
        <translation>une reprise en main de la mission est déjà en cours de confirmation</translation>
    </message>
    <message>
        <source>Take over the mission?</source>
        <translation>Reprendre la mission en main ?</translation>
    </message>
    <message>
        <source>%1 is running a mission (waypoint %2 of %3). Driving it by hand pauses the mission first; Resume in the mission panel continues it.</source>
        <translation>%1 exécute une mission (point %2 sur %3). La conduite manuelle met d&apos;abord la mission en pause ; « Reprendre » dans le panneau Mission la poursuit.</translation>
    </message>
    <message>
        <source>&amp;Pause and drive</source>
        <translation>&amp;Pause et conduite</translation>
    </message>
    <message>
        <source>&amp;Keep the mission</source>
        <translation>&amp;Garder la mission</translation>
    </message>
    <message>
        <source>no command gate</source>
        <translation>aucun filtre de commandes</translation>
    </message>
    <message>
        <source>the operator kept the mission</source>
        <translation>l&apos;opérateur a gardé la mission</translation>
    </message>
</context>
<context>
    <name>ocu::OperatorSession</name>
    <message>
        <source>idle for %1 s</source>
        <translation>inactif depuis %1 s</translation>
    </message>
    <message>
        <source>no authentication</source>
        <translation>aucune authentification</translation>
    </message>
    <message>
        <source>sign-in refused: %1</source>
        <translation>connexion refusée : %1</translation>
    </message>
    <message>
        <source>switch cancelled: control kept by %1</source>
        <translation>changement annulé : le contrôle reste à %1</translation>
    </message>
    <message>
        <source>operator switched to %1</source>
        <translation>opérateur changé pour %1</translation>
    </message>
    <message>
        <source>signed in as %1 after %2</source>
        <translation>connecté en tant que %1 après %2</translation>
    </message>
    <message>
        <source>on demand</source>
        <translation>à la demande</translation>
    </message>
    <message>
        <source>console locked: %1</source>
        <translation>console verrouillée : %1</translation>
    </message>
    <message>
        <source>unlock refused: %1</source>
        <translation>déverrouillage refusé : %1</translation>
    </message>
    <message>
        <source>console unlocked</source>
        <translation>console déverrouillée</translation>
    </message>
</context>
<context>
    <name>ocu::OperatorUi</name>
    <message>
        <source>S&amp;witch operator…</source>
        <translation>Changer d&apos;&amp;opérateur…</translation>
    </message>
    <message>
        <source>&amp;Lock</source>
        <translation>&amp;Verrouiller</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>Operator %1, role %2, at console %3 (File › Switch operator…)</source>
        <translation>Opérateur %1, rôle %2, sur la console %3 (Fichier › Changer d&apos;opérateur…)</translation>
    </message>
    <message>
        <source>Locked by %1 (%2)</source>
        <translation>Verrouillée par %1 (%2)</translation>
    </message>
    <message>
        <source>Switch operator</source>
        <translation>Changer d&apos;opérateur</translation>
    </message>
    <message>
        <source>The next operator signs in with their own password. The machines keep running.</source>
        <translation>L&apos;opérateur suivant se connecte avec son propre mot de passe. Les machines continuent de fonctionner.</translation>
    </message>
    <message>
        <source>no operator session</source>
        <translation>aucune session opérateur</translation>
    </message>
    <message>
        <source>Release control</source>
        <translation>Libérer le contrôle</translation>
    </message>
    <message>
        <source>The new operator&apos;s role may not control machines. Release control of %1?</source>
        <translation>Le rôle du nouvel opérateur ne permet pas de contrôler des machines. Libérer le contrôle de %1 ?</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Déverrouiller</translation>
    </message>
    <message>
        <source>Enter your password to unlock the console.</source>
        <translation>Saisissez votre mot de passe pour déverrouiller la console.</translation>
    </message>
</context>
<context>
    <name>ocu::OsyrisBridge</name>
    <message>
        <source>OSYRIS: %1</source>
        <translation>OSYRIS : %1</translation>
    </message>
    <message>
        <source>joined, waiting for stations</source>
        <translation>connecté, en attente des stations</translation>
    </message>
    <message>
        <source>Machine %1</source>
        <translation>Machine %1</translation>
    </message>
    <message>
        <source>vibration on</source>
        <translation>vibration activée</translation>
    </message>
    <message>
        <source>vibration off</source>
        <translation>vibration désactivée</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>marche avant</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>marche arrière</translation>
    </message>
    <message>
        <source>standing</source>
        <translation>à l&apos;arrêt</translation>
    </message>
    <message>
        <source>GPS shadow</source>
        <translation>masquage GPS</translation>
    </message>
    <message>
        <source>position not valid</source>
        <translation>position non valide</translation>
    </message>
    <message>
        <source>low position accuracy</source>
        <translation>faible précision de position</translation>
    </message>
    <message>
        <source>high accuracy</source>
        <translation>haute précision</translation>
    </message>
    <message>
        <source>medium accuracy</source>
        <translation>précision moyenne</translation>
    </message>
    <message>
        <source>stations heard</source>
        <translation>stations reçues</translation>
    </message>
    <message>
        <source>ping: &quot;idx&quot; must be a station index 0-253</source>
        <translation>ping : &quot;idx&quot; doit être un index de station 0-253</translation>
    </message>
    <message>
        <source>OSYRIS station stopped</source>
        <translation>station OSYRIS arrêtée</translation>
    </message>
    <message>
        <source>implausible position ignored (slot %1): %2</source>
        <translation>position invraisemblable ignorée (slot %1) : %2</translation>
    </message>
    <message>
        <source>%1: %2 positions given up as unobtainable (slots %3); their cells are marked incomplete</source>
        <translation>%1 : %2 positions abandonnées comme impossibles à obtenir (slots %3) ; leurs cellules sont marquées incomplètes</translation>
    </message>
    <message>
        <source>station %1</source>
        <translation>station %1</translation>
    </message>
    <message>
        <source>Message from %1 (%2): %3</source>
        <translation>Message de %1 (%2) : %3</translation>
    </message>
    <message>
        <source>%1 refused: the OSYRIS station is not running; nothing sent</source>
        <translation>%1 refusé : la station OSYRIS ne tourne pas ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>%1 refused: no OSYRIS station heard on %2:%3 yet; nothing sent</source>
        <translation>%1 refusé : aucune station OSYRIS encore entendue sur %2:%3 ; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <source>STOP message</source>
        <translation>message STOP</translation>
    </message>
    <message>
        <source>not an OSYRIS machine</source>
        <translation>pas une machine OSYRIS</translation>
    </message>
    <message>
        <source>OSYRIS machines carry no stop state to clear</source>
        <translation>les machines OSYRIS n&apos;ont aucun état d&apos;arrêt à lever</translation>
    </message>
    <message>
        <source>send_text: &quot;%1&quot; is not an OSYRIS station</source>
        <translation>send_text : « %1 » n&apos;est pas une station OSYRIS</translation>
    </message>
    <message>
        <source>send_text: &quot;text&quot; must be 1 to 79 bytes (CmMsg)</source>
        <translation>send_text : « text » doit faire de 1 à 79 octets (CmMsg)</translation>
    </message>
    <message>
        <source>no station heard for %1 s</source>
        <translation>aucune station entendue depuis %1 s</translation>
    </message>
</context>
<context>
    <name>ocu::OwnPosition</name>
    <message>
        <source>position source error %1</source>
        <translation>erreur de la source de position %1</translation>
    </message>
    <message>
        <source>no system position source available</source>
        <translation>aucune source de position système disponible</translation>
    </message>
    <message>
        <source>cannot open NMEA log %1: %2</source>
        <translation>impossible d&apos;ouvrir le journal NMEA %1 : %2</translation>
    </message>
    <message>
        <source>no NMEA device</source>
        <translation>aucun périphérique NMEA</translation>
    </message>
</context>
<context>
    <name>ocu::PanTiltController</name>
    <message>
        <source>camera control disabled</source>
        <translation>contrôle caméra désactivé</translation>
    </message>
    <message>
        <source>hat released</source>
        <translation>chapeau chinois relâché</translation>
    </message>
    <message>
        <source>joystick unplugged</source>
        <translation>joystick débranché</translation>
    </message>
    <message>
        <source>keys released</source>
        <translation>touches relâchées</translation>
    </message>
    <message>
        <source>stick released</source>
        <translation>manche relâché</translation>
    </message>
    <message>
        <source>input released</source>
        <translation>commande relâchée</translation>
    </message>
</context>
<context>
    <name>ocu::PassCountPanel</name>
    <message>
        <source>Pass count (discrete)</source>
        <translation>Nombre de passes (discret)</translation>
    </message>
    <message>
        <source>Summary (below / within / above)</source>
        <translation>Synthèse (en dessous / dans / au-dessus)</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <source>Target passes</source>
        <translation>Passes cibles</translation>
    </message>
    <message>
        <source>No pass-count data</source>
        <translation>Aucune donnée de passes</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%1&apos;&gt;■&lt;/span&gt; below %2&lt;/td&gt;&lt;td align=right&gt;%3 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%4&apos;&gt;■&lt;/span&gt; within %5–%6&lt;/td&gt;&lt;td align=right&gt;%7 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%8&apos;&gt;■&lt;/span&gt; above %6&lt;/td&gt;&lt;td align=right&gt;%9 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;covered area&lt;/td&gt;&lt;td align=right&gt;%10 m²&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%1&apos;&gt;■&lt;/span&gt; sous %2&lt;/td&gt;&lt;td align=right&gt;%3 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%4&apos;&gt;■&lt;/span&gt; dans %5–%6&lt;/td&gt;&lt;td align=right&gt;%7 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;span style=&apos;color:%8&apos;&gt;■&lt;/span&gt; au-dessus de %6&lt;/td&gt;&lt;td align=right&gt;%9 %&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;surface couverte&lt;/td&gt;&lt;td align=right&gt;%10 m²&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Passes</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>Lift</source>
        <translation>Couche</translation>
    </message>
    <message>
        <source>Filters</source>
        <translation>Filtres</translation>
    </message>
    <message>
        <source>Vibrating only</source>
        <translation>Avec vibration uniquement</translation>
    </message>
    <message>
        <source>Static only</source>
        <translation>Statique uniquement</translation>
    </message>
    <message>
        <source>Vibrating and static</source>
        <translation>Avec vibration et statique</translation>
    </message>
    <message>
        <source>Both directions</source>
        <translation>Les deux sens</translation>
    </message>
    <message>
        <source>Forward only</source>
        <translation>Avant uniquement</translation>
    </message>
    <message>
        <source>Backward only</source>
        <translation>Arrière uniquement</translation>
    </message>
    <message>
        <source> km/h</source>
        <translation> km/h</translation>
    </message>
    <message>
        <source>any</source>
        <translation>toutes</translation>
    </message>
    <message>
        <source>Time window</source>
        <translation>Plage horaire</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>one lift</source>
        <translation>une couche</translation>
    </message>
    <message>
        <source>Lifts are elevation bands of this thickness in the machines&apos; heights</source>
        <translation>Les couches sont des tranches d&apos;altitude de cette épaisseur dans les hauteurs des machines</translation>
    </message>
    <message>
        <source>Vibration</source>
        <translation>Vibration</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Sens</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Lift thickness</source>
        <translation>Épaisseur de couche</translation>
    </message>
    <message>
        <source>Top-most lift</source>
        <translation>Couche la plus haute</translation>
    </message>
    <message>
        <source>Lift %1 (z %2 – %3 m)</source>
        <translation>Couche %1 (z %2 – %3 m)</translation>
    </message>
</context>
<context>
    <name>ocu::PlatformServicesWidget</name>
    <message>
        <source>Set mode</source>
        <translation>Définir le mode</translation>
    </message>
    <message>
        <source>Set state…</source>
        <translation>Définir l&apos;état…</translation>
    </message>
    <message>
        <source>Emergency state</source>
        <translation>État d&apos;urgence</translation>
    </message>
    <message>
        <source>Reset trip</source>
        <translation>Remettre le trajet à zéro</translation>
    </message>
    <message>
        <source>Platform state</source>
        <translation>État de la plateforme</translation>
    </message>
    <message>
        <source>Put the whole platform in its emergency state: every component halts and refuses commands until it is set back to operational (AEP-4818 §6.2.6)</source>
        <translation>Mettre toute la plateforme dans son état d&apos;urgence : chaque composant s&apos;arrête et refuse les commandes jusqu&apos;au retour à l&apos;état opérationnel (AEP-4818 §6.2.6)</translation>
    </message>
    <message>
        <source>Platform mode:</source>
        <translation>Mode de la plateforme :</translation>
    </message>
    <message>
        <source>Platform state:</source>
        <translation>État de la plateforme :</translation>
    </message>
    <message>
        <source>Odometer:</source>
        <translation>Odomètre :</translation>
    </message>
    <message>
        <source>Put %1 in the platform state &quot;%2&quot;?</source>
        <translation>Mettre %1 dans l&apos;état de plateforme « %2 » ?</translation>
    </message>
    <message>
        <source>not offered</source>
        <translation>non proposé</translation>
    </message>
    <message>
        <source>not reported yet</source>
        <translation>pas encore signalé</translation>
    </message>
    <message>
        <source> (last request refused: %1)</source>
        <translation> (dernière demande refusée : %1)</translation>
    </message>
    <message>
        <source>%1 · trip %2</source>
        <translation>%1 · trajet %2</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Comms-lost policy: offered (%1 %2); setting a policy waits for a published message layout</source>
        <translation>Politique de perte de liaison : proposée (%1 %2) ; sa définition attend un format de message publié</translation>
    </message>
    <message>
        <source>Comms-lost policy: not offered by this vehicle</source>
        <translation>Politique de perte de liaison : non proposée par ce véhicule</translation>
    </message>
</context>
<context>
    <name>ocu::ProductionModel</name>
    <message>
        <source>Shift</source>
        <translation>Poste</translation>
    </message>
    <message>
        <source>way %1</source>
        <translation>voie %1</translation>
    </message>
    <message>
        <source>unknown shovel</source>
        <translation>pelle inconnue</translation>
    </message>
    <message>
        <source>unknown dump</source>
        <translation>déversement inconnu</translation>
    </message>
</context>
<context>
    <name>ocu::ProductionView</name>
    <message>
        <source>Plan (t/shift):</source>
        <translation>Plan (t/poste) :</translation>
    </message>
    <message>
        <source>Tonnes planned for the shift (0: no plan)</source>
        <translation>Tonnes prévues pour le poste (0 : aucun plan)</translation>
    </message>
    <message>
        <source>Shift &amp;report…</source>
        <translation>&amp;Rapport de poste…</translation>
    </message>
    <message>
        <source>Write the shift report as PDF and CSV</source>
        <translation>Écrire le rapport de poste en PDF et CSV</translation>
    </message>
    <message>
        <source>New shift</source>
        <translation>Nouveau poste</translation>
    </message>
    <message>
        <source>Start counting a new shift now (the current figures are discarded)</source>
        <translation>Commencer à compter un nouveau poste maintenant (les chiffres actuels sont abandonnés)</translation>
    </message>
    <message>
        <source>Start a new shift now? The current shift&apos;s figures are discarded; write the shift report first.</source>
        <translation>Commencer un nouveau poste maintenant ? Les chiffres du poste actuel sont abandonnés ; écrivez d&apos;abord le rapport de poste.</translation>
    </message>
    <message>
        <source>Trucks</source>
        <translation>Camions</translation>
    </message>
    <message>
        <source>Shovels</source>
        <translation>Pelles</translation>
    </message>
    <message>
        <source>Dumps</source>
        <translation>Déversements</translation>
    </message>
    <message>
        <source>Truck</source>
        <translation>Camion</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Zone</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>Chargements</translation>
    </message>
    <message>
        <source>Tonnes</source>
        <translation>Tonnes</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Queue</source>
        <translation>Attente</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Mise en place</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Chargement</translation>
    </message>
    <message>
        <source>Haul</source>
        <translation>Transport</translation>
    </message>
    <message>
        <source>Dump</source>
        <translation>Déversement</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>Retour</translation>
    </message>
    <message>
        <source>Cycle parts: average minutes:seconds per cycle</source>
        <translation>Parties du cycle : minutes:secondes moyennes par cycle</translation>
    </message>
    <message>
        <source>%1 % of the %2 t due by now</source>
        <translation>%1 % des %2 t dues à ce stade</translation>
    </message>
    <message>
        <source>no plan set</source>
        <translation>aucun plan défini</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 t&lt;/b&gt; in &lt;b&gt;%2 loads&lt;/b&gt; · %3 cycles, average %4 · %5</source>
        <translation>&lt;b&gt;%1 t&lt;/b&gt; en &lt;b&gt;%2 chargements&lt;/b&gt; · %3 cycles, moyenne %4 · %5</translation>
    </message>
    <message>
        <source>Shift report</source>
        <translation>Rapport de poste</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Written:
%1
%2</source>
        <translation>Écrit :
%1
%2</translation>
    </message>
    <message>
        <source>The shift report was not written: %1</source>
        <translation>Le rapport de poste n&apos;a pas été écrit : %1</translation>
    </message>
</context>
<context>
    <name>ocu::ReplayTimeline</name>
    <message>
        <source>Step back (Left)</source>
        <translation>Pas en arrière (Gauche)</translation>
    </message>
    <message>
        <source>Play backwards</source>
        <translation>Lire à rebours</translation>
    </message>
    <message>
        <source>Play / pause (Space)</source>
        <translation>Lecture / pause (Espace)</translation>
    </message>
    <message>
        <source>Step forward (Right)</source>
        <translation>Pas en avant (Droite)</translation>
    </message>
    <message>
        <source>Speed (+ / -)</source>
        <translation>Vitesse (+ / -)</translation>
    </message>
    <message>
        <source>HH:MM:SS or seconds</source>
        <translation>HH:MM:SS ou secondes</translation>
    </message>
    <message>
        <source>Go to an exact time: HH:MM:SS[.mmm] (UTC), seconds after the start, or ISO 8601; Enter</source>
        <translation>Aller à une heure exacte : HH:MM:SS[.mmm] (UTC), secondes après le début ou ISO 8601 ; Entrée</translation>
    </message>
    <message>
        <source>Not a time: %1</source>
        <translation>Pas une heure : %1</translation>
    </message>
</context>
<context>
    <name>ocu::SdlJoystickInput</name>
    <message>
        <source>No joystick</source>
        <translation>Aucun joystick</translation>
    </message>
</context>
<context>
    <name>ocu::SignInDialog</name>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Utilisateur :</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Mot de passe :</translation>
    </message>
    <message>
        <source>&amp;Sign in</source>
        <translation>&amp;Se connecter</translation>
    </message>
    <message>
        <source>no check</source>
        <translation>aucune vérification</translation>
    </message>
</context>
<context>
    <name>ocu::Site3DFeed</name>
    <message>
        <source>below %1</source>
        <translation>sous %1</translation>
    </message>
    <message>
        <source>%1–%2</source>
        <translation>%1–%2</translation>
    </message>
    <message>
        <source>above %1</source>
        <translation>au-dessus de %1</translation>
    </message>
</context>
<context>
    <name>ocu::Site3DView</name>
    <message>
        <source>Orbit</source>
        <translation>Orbite</translation>
    </message>
    <message>
        <source>Free orbit camera (drag to rotate, wheel to zoom)</source>
        <translation>Caméra orbitale libre (glisser pour pivoter, molette pour zoomer)</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>Suivre</translation>
    </message>
    <message>
        <source>Keep the selected machine in the centre</source>
        <translation>Garder la machine sélectionnée au centre</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Dessus</translation>
    </message>
    <message>
        <source>Top-down view, north up</source>
        <translation>Vue de dessus, nord en haut</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Réinitialiser la vue</translation>
    </message>
    <message>
        <source>3D view unavailable: %1</source>
        <translation>Vue 3D indisponible : %1</translation>
    </message>
</context>
<context>
    <name>ocu::SiteMapView</name>
    <message>
        <source>below (&lt;%1)</source>
        <translation>sous (&lt;%1)</translation>
    </message>
    <message>
        <source>within %1–%2</source>
        <translation>dans %1–%2</translation>
    </message>
    <message>
        <source>above (&gt;%1)</source>
        <translation>au-dessus (&gt;%1)</translation>
    </message>
    <message>
        <source>Passes · target %1–%2</source>
        <translation>Passes · cible %1–%2</translation>
    </message>
    <message>
        <source>type unknown</source>
        <translation>type inconnu</translation>
    </message>
    <message>
        <source>Status: %1</source>
        <translation>État : %1</translation>
    </message>
    <message>
        <source>Mode: %1</source>
        <translation>Mode : %1</translation>
    </message>
    <message>
        <source>Speed: %1 km/h · heading %2°</source>
        <translation>Vitesse : %1 km/h · cap %2°</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Arrêté : %1</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>oui</translation>
    </message>
    <message>
        <source>Health: %1</source>
        <translation>Santé : %1</translation>
    </message>
    <message>
        <source>Control: %1</source>
        <translation>Contrôle : %1</translation>
    </message>
    <message>
        <source>Link: %1 · data %2 s ago</source>
        <translation>Liaison : %1 · données il y a %2 s</translation>
    </message>
</context>
<context>
    <name>ocu::SiteRuntime</name>
    <message>
        <source>Crew messages</source>
        <translation>Messages à l’équipe</translation>
    </message>
    <message>
        <source>Crew messages (%1)</source>
        <translation>Messages à l’équipe (%1)</translation>
    </message>
    <message>
        <source>Simulated site: %1</source>
        <translation>Site simulé : %1</translation>
    </message>
    <message>
        <source>Own position: %1</source>
        <translation>Position propre : %1</translation>
    </message>
    <message>
        <source>This build has no 3D view (configured with OCU_WITH_VTK=OFF).</source>
        <translation>Cette version n&apos;a pas de vue 3D (configurée avec OCU_WITH_VTK=OFF).</translation>
    </message>
    <message>
        <source>console started</source>
        <translation>console démarrée</translation>
    </message>
    <message>
        <source>control-room history connected</source>
        <translation>historique de la salle de contrôle connecté</translation>
    </message>
    <message>
        <source>control-room history unavailable (kept locally, back-filled on return): %1</source>
        <translation>historique de la salle de contrôle indisponible (conservé localement, complété au retour) : %1</translation>
    </message>
    <message>
        <source>Control-room history: %1</source>
        <translation>Historique de la salle de contrôle : %1</translation>
    </message>
    <message>
        <source>Flight recorder: %1</source>
        <translation>Enregistreur de vol : %1</translation>
    </message>
    <message>
        <source>Recording this run to %1</source>
        <translation>Cette exécution est enregistrée dans %1</translation>
    </message>
    <message>
        <source>Map background not shown: %1</source>
        <translation>Fond de carte non affiché : %1</translation>
    </message>
    <message>
        <source>3D terrain not shown: %1</source>
        <translation>Terrain 3D non affiché : %1</translation>
    </message>
    <message>
        <source>STOP button ready</source>
        <translation>Bouton STOP prêt</translation>
    </message>
    <message>
        <source>STOP button not connected</source>
        <translation>Bouton STOP non connecté</translation>
    </message>
    <message>
        <source>%1: %2 triggers STOP ALL</source>
        <translation>%1 : %2 déclenche l&apos;ARRÊT GÉNÉRAL</translation>
    </message>
    <message>
        <source>No device with %1 is connected; STOP ALL stays on F12, Ctrl+Shift+Space and the toolbar</source>
        <translation>Aucun appareil avec %1 n&apos;est connecté ; ARRÊT GÉNÉRAL reste sur F12, Ctrl+Maj+Espace et la barre d&apos;outils</translation>
    </message>
    <message>
        <source>Areas and reports</source>
        <translation>Zones et rapports</translation>
    </message>
    <message>
        <source>console closed</source>
        <translation>console fermée</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopController</name>
    <message>
        <source>control lost or disabled</source>
        <translation>contrôle perdu ou désactivé</translation>
    </message>
    <message>
        <source>joystick released</source>
        <translation>joystick relâché</translation>
    </message>
    <message>
        <source>joystick unplugged</source>
        <translation>joystick débranché</translation>
    </message>
    <message>
        <source>dead-man key released</source>
        <translation>touche homme mort relâchée</translation>
    </message>
    <message>
        <source>keys released</source>
        <translation>touches relâchées</translation>
    </message>
    <message>
        <source>stick released</source>
        <translation>manche relâché</translation>
    </message>
    <message>
        <source>input released</source>
        <translation>commande relâchée</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopPanel</name>
    <message>
        <source>E-STOP</source>
        <translation>Arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>Hold to clear emergency</source>
        <translation>Maintenir pour lever l&apos;urgence</translation>
    </message>
    <message>
        <source>Emergency stop of this vehicle (Space or Esc). Never asks for confirmation.</source>
        <translation>Arrêt d&apos;urgence de ce véhicule (Espace ou Échap). Ne demande jamais de confirmation.</translation>
    </message>
    <message>
        <source>Velocity (m/s, rad/s)</source>
        <translation>Vitesse (m/s, rad/s)</translation>
    </message>
    <message>
        <source>Wrench effort (%)</source>
        <translation>Effort (%)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Limite de vitesse</translation>
    </message>
    <message>
        <source>Joystick</source>
        <translation>Joystick</translation>
    </message>
    <message>
        <source>window lost focus</source>
        <translation>la fenêtre a perdu le focus</translation>
    </message>
    <message>
        <source>vehicle changed</source>
        <translation>véhicule changé</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>none connected</source>
        <translation>aucun connecté</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>No JAUS vehicle selected</source>
        <translation>Aucun véhicule JAUS sélectionné</translation>
    </message>
    <message>
        <source>Select a vehicle in the fleet list or the JAUS control panel, then take control.</source>
        <translation>Sélectionner un véhicule dans la liste de la flotte ou le panneau de contrôle JAUS, puis prendre le contrôle.</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>MONITOR role: driving disabled</source>
        <translation>Rôle MONITOR : conduite désactivée</translation>
    </message>
    <message>
        <source>not controlled by this console: take control first</source>
        <translation>non contrôlé par cette console : prendre d&apos;abord le contrôle</translation>
    </message>
    <message>
        <source>controlled by this console</source>
        <translation>contrôlé par cette console</translation>
    </message>
    <message>
        <source>EMERGENCY — hold the clear button to release</source>
        <translation>EMERGENCY — maintenir le bouton de levée pour libérer</translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>liaison %1</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>état %1</translation>
    </message>
    <message>
        <source>drive session open</source>
        <translation>session de conduite ouverte</translation>
    </message>
    <message>
        <source>drive session closed (vehicle stops after its 1 s drive timeout)</source>
        <translation>session de conduite fermée (le véhicule s&apos;arrête après son délai de conduite de 1 s)</translation>
    </message>
    <message>
        <source>speed %1 m/s</source>
        <translation>vitesse %1 m/s</translation>
    </message>
    <message>
        <source>heading %1°</source>
        <translation>cap %1°</translation>
    </message>
    <message>
        <source>pose %1, %2</source>
        <translation>pose %1, %2</translation>
    </message>
    <message>
        <source>local %1 / %2 m</source>
        <translation>local %1 / %2 m</translation>
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
        <translation>le panneau de téléopération a perdu le focus clavier</translation>
    </message>
    <message>
        <source>teleop panel hidden</source>
        <translation>panneau de téléopération masqué</translation>
    </message>
    <message>
        <source>Mapping…</source>
        <translation>Affectation…</translation>
    </message>
    <message>
        <source>Choose the joystick axes, their direction and the dead zone</source>
        <translation>Choisir les axes du joystick, leur sens et la zone morte</translation>
    </message>
    <message>
        <source>joystick mapping</source>
        <translation>affectation du joystick</translation>
    </message>
    <message>
        <source>Stick: camera</source>
        <translation>Manche : caméra</translation>
    </message>
    <message>
        <source>The on-screen stick pans and tilts the camera instead of driving</source>
        <translation>Le manche à l&apos;écran oriente la caméra au lieu de conduire</translation>
    </message>
    <message>
        <source>Keyboard: hold Shift (dead-man) and use W/A/S/D or the arrows. Camera: J/L pan, I/K tilt (or the joystick hat).</source>
        <translation>Clavier : maintenir Maj (homme mort) et utiliser W/A/S/D ou les flèches. Caméra : J/L panoramique, I/K inclinaison (ou le chapeau chinois du joystick).</translation>
    </message>
    <message>
        <source>camera changed</source>
        <translation>caméra changée</translation>
    </message>
    <message>
        <source>teleop panel closed</source>
        <translation>panneau de téléopération fermé</translation>
    </message>
    <message>
        <source>Camera pan-tilt refused: %1</source>
        <translation>Orientation de la caméra refusée : %1</translation>
    </message>
    <message>
        <source>no command gate: driving is not possible</source>
        <translation>aucun contrôleur de commandes : conduite impossible</translation>
    </message>
    <message>
        <source>teleop input</source>
        <translation>entrée de téléopération</translation>
    </message>
    <message>
        <source>Drive session NOT started: %1</source>
        <translation>Session de conduite NON démarrée : %1</translation>
    </message>
    <message>
        <source>Drive session end: zero commands NOT sent: %1</source>
        <translation>Fin de la session de conduite : commandes nulles NON envoyées : %1</translation>
    </message>
    <message>
        <source>Driving stopped: %1</source>
        <translation>Conduite arrêtée : %1</translation>
    </message>
    <message>
        <source>the link to %1 is %2</source>
        <translation>la liaison avec %1 est %2</translation>
    </message>
    <message>
        <source>%1 is in EMERGENCY</source>
        <translation>%1 est en URGENCE</translation>
    </message>
    <message>
        <source>this console no longer controls %1</source>
        <translation>cette console ne contrôle plus %1</translation>
    </message>
    <message>
        <source>driving is not allowed</source>
        <translation>la conduite n&apos;est pas autorisée</translation>
    </message>
    <message>
        <source>EMERGENCY</source>
        <translation>URGENCE</translation>
    </message>
    <message>
        <source>driving held (video)</source>
        <translation>conduite suspendue (vidéo)</translation>
    </message>
    <message>
        <source>ready to drive</source>
        <translation>prêt à conduire</translation>
    </message>
    <message>
        <source>not driving</source>
        <translation>ne conduit pas</translation>
    </message>
    <message>
        <source>video window closed or lost focus</source>
        <translation>fenêtre vidéo fermée ou focus perdu</translation>
    </message>
    <message>
        <source>teleop video hidden</source>
        <translation>vidéo de téléopération masquée</translation>
    </message>
    <message>
        <source>The vehicle runs a mission: confirm to pause it before driving</source>
        <translation>Le véhicule exécute une mission : confirmer sa mise en pause avant de conduire</translation>
    </message>
    <message>
        <source>Mission paused: driving by hand (Resume in the mission panel)</source>
        <translation>Mission en pause : conduite manuelle (Reprendre dans le panneau Mission)</translation>
    </message>
</context>
<context>
    <name>ocu::TeleopVideoPane</name>
    <message>
        <source>Teleoperation video</source>
        <translation>Vidéo de téléopération</translation>
    </message>
    <message>
        <source>Full screen</source>
        <translation>Plein écran</translation>
    </message>
    <message>
        <source>Resume driving</source>
        <translation>Reprendre la conduite</translation>
    </message>
    <message>
        <source>No camera on this vehicle</source>
        <translation>Aucune caméra sur ce véhicule</translation>
    </message>
    <message>
        <source>Camera shown (announced by the vehicle or configured for it)</source>
        <translation>Caméra affichée (annoncée par le véhicule ou configurée pour lui)</translation>
    </message>
    <message>
        <source>Show the video full screen (Esc returns); driving keys keep working there</source>
        <translation>Afficher la vidéo en plein écran (Échap pour revenir) ; les touches de conduite y fonctionnent toujours</translation>
    </message>
    <message>
        <source>The video watchdog stopped driving: resume once the video is back</source>
        <translation>Le chien de garde vidéo a arrêté la conduite : reprendre une fois la vidéo revenue</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>camera %1</source>
        <translation>caméra %1</translation>
    </message>
    <message>
        <source> (configured)</source>
        <translation> (configurée)</translation>
    </message>
    <message>
        <source>%1 — pan-tilt: J/L/I/K, the stick&apos;s camera mode or the joystick hat</source>
        <translation>%1 — orientation : J/L/I/K, le mode caméra du manche ou le chapeau chinois du joystick</translation>
    </message>
    <message>
        <source>no camera</source>
        <translation>aucune caméra</translation>
    </message>
</context>
<context>
    <name>ocu::TimelineMarkerStrip</name>
    <message>
        <source>command: </source>
        <translation>commande : </translation>
    </message>
    <message>
        <source>alarm: </source>
        <translation>alarme : </translation>
    </message>
</context>
<context>
    <name>ocu::VehicleDetailsWidget</name>
    <message>
        <source>Item</source>
        <translation>Élément</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valeur</translation>
    </message>
    <message>
        <source>Identification</source>
        <translation>Identification</translation>
    </message>
    <message>
        <source>Call sign</source>
        <translation>Indicatif</translation>
    </message>
    <message>
        <source>Subsystem ID</source>
        <translation>ID de sous-système</translation>
    </message>
    <message>
        <source>Endpoint</source>
        <translation>Point d&apos;accès</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Liaison</translation>
    </message>
    <message>
        <source>State</source>
        <translation>État</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Accès</translation>
    </message>
    <message>
        <source>Management</source>
        <translation>Gestion</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>inconnu</translation>
    </message>
    <message>
        <source>Emergency</source>
        <translation>Urgence</translation>
    </message>
    <message>
        <source>YES</source>
        <translation>OUI</translation>
    </message>
    <message>
        <source>no</source>
        <translation>non</translation>
    </message>
    <message>
        <source>Drive session</source>
        <translation>Session de conduite</translation>
    </message>
    <message>
        <source>open</source>
        <translation>ouverte</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>fermée</translation>
    </message>
    <message>
        <source>Access timeout</source>
        <translation>Délai d&apos;accès</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Platform</source>
        <translation>Plateforme</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Steering</source>
        <translation>Direction</translation>
    </message>
    <message>
        <source>Ackermann</source>
        <translation>Ackermann</translation>
    </message>
    <message>
        <source>skid steer</source>
        <translation>direction par glissement</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Longueur</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Largeur</translation>
    </message>
    <message>
        <source>Max forward speed</source>
        <translation>Vitesse max. avant</translation>
    </message>
    <message>
        <source>Max reverse speed</source>
        <translation>Vitesse max. arrière</translation>
    </message>
    <message>
        <source>Max rotational speed</source>
        <translation>Vitesse de rotation max.</translation>
    </message>
    <message>
        <source>Specifications</source>
        <translation>Caractéristiques</translation>
    </message>
    <message>
        <source>not reported yet</source>
        <translation>pas encore signalé</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Pose</translation>
    </message>
    <message>
        <source>Latitude</source>
        <translation>Latitude</translation>
    </message>
    <message>
        <source>Longitude</source>
        <translation>Longitude</translation>
    </message>
    <message>
        <source>Altitude</source>
        <translation>Altitude</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Cap</translation>
    </message>
    <message>
        <source>Local X</source>
        <translation>X local</translation>
    </message>
    <message>
        <source>Local Y</source>
        <translation>Y local</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Yaw rate</source>
        <translation>Vitesse de lacet</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Santé</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Synthèse</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Nœud %1</translation>
    </message>
    <message>
        <source>Services</source>
        <translation>Services</translation>
    </message>
    <message>
        <source>Subsystem %1</source>
        <translation>Sous-système %1</translation>
    </message>
    <message>
        <source>Platform services</source>
        <translation>Services de plateforme</translation>
    </message>
    <message>
        <source>not offered</source>
        <translation>non proposé</translation>
    </message>
    <message>
        <source>Platform mode</source>
        <translation>Mode de la plateforme</translation>
    </message>
    <message>
        <source>Platform state</source>
        <translation>État de la plateforme</translation>
    </message>
    <message>
        <source>Lights</source>
        <translation>Feux</translation>
    </message>
    <message>
        <source>all off</source>
        <translation>tous éteints</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Odometer</source>
        <translation>Odomètre</translation>
    </message>
    <message>
        <source>Trip</source>
        <translation>Trajet</translation>
    </message>
    <message>
        <source>Comms-lost policy service</source>
        <translation>Service de politique de perte de liaison</translation>
    </message>
</context>
<context>
    <name>ocu::VideoPlayer</name>
    <message>
        <source>no video</source>
        <translation>pas de vidéo</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>connexion en cours</translation>
    </message>
    <message>
        <source>playing</source>
        <translation>lecture</translation>
    </message>
    <message>
        <source>video LOST</source>
        <translation>vidéo PERDUE</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>reconnexion</translation>
    </message>
    <message>
        <source>no video URL</source>
        <translation>aucune URL vidéo</translation>
    </message>
    <message>
        <source>not an RTSP URL: %1</source>
        <translation>pas une URL RTSP : %1</translation>
    </message>
    <message>
        <source>GStreamer elements missing</source>
        <translation>éléments GStreamer manquants</translation>
    </message>
    <message>
        <source>cannot link the video pipeline</source>
        <translation>impossible de relier le pipeline vidéo</translation>
    </message>
    <message>
        <source>the video pipeline did not start</source>
        <translation>le pipeline vidéo n&apos;a pas démarré</translation>
    </message>
    <message>
        <source>no video from %1</source>
        <translation>pas de vidéo de %1</translation>
    </message>
    <message>
        <source>no frame for %1 ms</source>
        <translation>aucune image depuis %1 ms</translation>
    </message>
</context>
<context>
    <name>ocu::VideoView</name>
    <message>
        <source>%1 fps</source>
        <translation>%1 i/s</translation>
    </message>
    <message>
        <source>frame age %1 ms</source>
        <translation>âge de l&apos;image %1 ms</translation>
    </message>
    <message>
        <source>frame age %1 ms (since arrival)</source>
        <translation>âge de l&apos;image %1 ms (depuis l&apos;arrivée)</translation>
    </message>
</context>
<context>
    <name>ocu::VideoWatchdog</name>
    <message>
        <source>video %1</source>
        <translation>vidéo %1</translation>
    </message>
    <message>
        <source>video frame %1 ms old (limit %2 ms)</source>
        <translation>image vidéo vieille de %1 ms (limite %2 ms)</translation>
    </message>
    <message>
        <source>VIDEO WATCHDOG stopped driving (%1); video is back: press Resume driving</source>
        <translation>Le CHIEN DE GARDE VIDÉO a arrêté la conduite (%1) ; la vidéo est revenue : appuyer sur Reprendre la conduite</translation>
    </message>
    <message>
        <source>VIDEO WATCHDOG stopped driving: %1</source>
        <translation>Le CHIEN DE GARDE VIDÉO a arrêté la conduite : %1</translation>
    </message>
    <message>
        <source>Driving waits for video (%1)</source>
        <translation>La conduite attend la vidéo (%1)</translation>
    </message>
</context>
<context>
    <name>ocu::VirtualStick</name>
    <message>
        <source>Drag to drive: up = forward, right = turn right. Release to stop.</source>
        <translation>Glisser pour conduire : haut = avant, droite = tourner à droite. Relâcher pour arrêter.</translation>
    </message>
    <message>
        <source>fwd</source>
        <translation>av.</translation>
    </message>
</context>
<context>
    <name>ocu::WorkspaceBar</name>
    <message>
        <source>Workspaces</source>
        <translation>Espaces de travail</translation>
    </message>
    <message>
        <source>%1 workspace (%2)</source>
        <translation>Espace de travail %1 (%2)</translation>
    </message>
    <message>
        <source>Dispatch</source>
        <translation>Répartition</translation>
    </message>
    <message>
        <source>Compaction</source>
        <translation>Compactage</translation>
    </message>
    <message>
        <source>UGV</source>
        <translation>UGV</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Surveiller</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Tout</translation>
    </message>
</context>
<context>
    <name>ocu::recording::Recorder</name>
    <message>
        <source>the recorder is already running</source>
        <translation>l&apos;enregistreur tourne déjà</translation>
    </message>
    <message>
        <source>%1 exists already; a recording is never overwritten</source>
        <translation>%1 existe déjà ; un enregistrement n&apos;est jamais écrasé</translation>
    </message>
    <message numerus="yes">
        <source>Flight recorder behind: %n record(s) dropped (%1 in all)</source>
        <translation>
            <numerusform>Enregistreur de vol en retard : %n enregistrement abandonné (%1 au total)</numerusform>
            <numerusform>Enregistreur de vol en retard : %n enregistrements abandonnés (%1 au total)</numerusform>
        </translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>impossible de créer %1 : %2</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>mémoire insuffisante</translation>
    </message>
    <message>
        <source>cannot create the recording schema in %1: %2</source>
        <translation>impossible de créer le schéma d&apos;enregistrement dans %1 : %2</translation>
    </message>
</context>
</TS>

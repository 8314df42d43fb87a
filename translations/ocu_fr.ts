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
</context>
<context>
    <name>QObject</name>
    <message>
        <source>STOP ALL</source>
        <translation>ARRÊT GÉNÉRAL</translation>
    </message>
    <message>
        <source>Stop every machine of every protocol (F12)</source>
        <translation>Arrêter toutes les machines de tous les protocoles (F12)</translation>
    </message>
    <message>
        <source>Production</source>
        <translation>Production</translation>
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
    <name>ocu::HoldToConfirmButton</name>
    <message>
        <source>Press and hold to confirm</source>
        <translation>Maintenir appuyé pour confirmer</translation>
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
        <source>Fleet definition discrepancy on %1: %2</source>
        <translation>Écart de définition de flotte sur %1 : %2</translation>
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
        <source>all-stop Apply sent on %1 (state shown as the AHS reports it)</source>
        <translation>Arrêt général Apply envoyé sur %1 (état affiché tel que signalé par l&apos;AHS)</translation>
    </message>
    <message>
        <source>unknown ISO 23725 machine: %1</source>
        <translation>machine ISO 23725 inconnue : %1</translation>
    </message>
    <message>
        <source>all-stop Apply sent to AHS %1 (ISO 23725 stops per AHS, not per machine)</source>
        <translation>Arrêt général Apply envoyé à l&apos;AHS %1 (ISO 23725 arrête par AHS, pas par machine)</translation>
    </message>
    <message>
        <source>all-stop Remove sent to AHS %1</source>
        <translation>Arrêt général Remove envoyé à l&apos;AHS %1</translation>
    </message>
    <message>
        <source>%1: unknown ISO 23725 link &quot;%2&quot;</source>
        <translation>%1 : liaison ISO 23725 inconnue « %2 »</translation>
    </message>
    <message>
        <source>all-stop Apply sent to %1</source>
        <translation>Arrêt général Apply envoyé à %1</translation>
    </message>
    <message>
        <source>all-stop Remove sent to %1</source>
        <translation>Arrêt général Remove envoyé à %1</translation>
    </message>
    <message>
        <source>map requested from %1</source>
        <translation>carte demandée à %1</translation>
    </message>
    <message>
        <source>reset_assignment: &quot;id&quot; must name an ISO 23725 machine</source>
        <translation>reset_assignment : &quot;id&quot; doit désigner une machine ISO 23725</translation>
    </message>
    <message>
        <source>assignment reset sent</source>
        <translation>réinitialisation de l&apos;affectation envoyée</translation>
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
    <message numerus="yes">
        <source>SetEmergency sent to %n vehicle(s) this console controls</source>
        <translation>
            <numerusform>SetEmergency envoyé à %n véhicule contrôlé par cette console</numerusform>
            <numerusform>SetEmergency envoyé à %n véhicules contrôlés par cette console</numerusform>
        </translation>
    </message>
    <message>
        <source>not a JAUS machine: %1</source>
        <translation>pas une machine JAUS : %1</translation>
    </message>
    <message>
        <source>SetEmergency sent to %1</source>
        <translation>SetEmergency envoyé à %1</translation>
    </message>
    <message>
        <source>clear emergency</source>
        <translation>levée de l&apos;urgence</translation>
    </message>
    <message>
        <source>ClearEmergency sent to %1</source>
        <translation>ClearEmergency envoyé à %1</translation>
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
        <source>drive command sent</source>
        <translation>commande de conduite envoyée</translation>
    </message>
    <message>
        <source>drive stopped</source>
        <translation>conduite arrêtée</translation>
    </message>
    <message>
        <source>control released on every subsystem</source>
        <translation>contrôle libéré sur tous les sous-systèmes</translation>
    </message>
    <message>
        <source>%1: &quot;id&quot; must name a JAUS machine such as &quot;jaus:101&quot;</source>
        <translation>%1 : &quot;id&quot; doit désigner une machine JAUS, p. ex. &quot;jaus:101&quot;</translation>
    </message>
    <message>
        <source>ReleaseControl sent to %1</source>
        <translation>ReleaseControl envoyé à %1</translation>
    </message>
    <message>
        <source>RequestControl sent to %1 with authority %2</source>
        <translation>RequestControl envoyé à %1 avec l&apos;autorité %2</translation>
    </message>
    <message>
        <source>Resume sent</source>
        <translation>Resume envoyé</translation>
    </message>
    <message>
        <source>Standby sent</source>
        <translation>Standby envoyé</translation>
    </message>
    <message>
        <source>Shutdown sent</source>
        <translation>Shutdown envoyé</translation>
    </message>
    <message>
        <source>Reset sent</source>
        <translation>Reset envoyé</translation>
    </message>
    <message>
        <source>drive: &quot;mode&quot; must be &quot;velocity&quot; or &quot;effort&quot;</source>
        <translation>drive : &quot;mode&quot; doit valoir &quot;velocity&quot; ou &quot;effort&quot;</translation>
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
        <source>driving %1 for %2 s</source>
        <translation>conduite de %1 pendant %2 s</translation>
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
</context>
<context>
    <name>ocu::MachineStopControls</name>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Hold to release</source>
        <translation>Maintenir pour libérer</translation>
    </message>
    <message>
        <source>No machine selected</source>
        <translation>Aucune machine sélectionnée</translation>
    </message>
    <message>
        <source>STOPPED%1</source>
        <translation>ARRÊTÉ%1</translation>
    </message>
    <message>
        <source>running</source>
        <translation>en marche</translation>
    </message>
    <message>
        <source>stop state unknown</source>
        <translation>état d&apos;arrêt inconnu</translation>
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
        <source>Stop every machine this console may stop: JAUS emergency stop to the vehicles it controls and ISO 23725 all-stop to every AHS link (F12 or Ctrl+Shift+Space). Stopping never asks for confirmation.</source>
        <translation>Arrêter toutes les machines que cette console peut arrêter : arrêt d&apos;urgence JAUS vers les véhicules qu&apos;elle contrôle et arrêt général ISO 23725 vers chaque liaison AHS (F12 ou Ctrl+Maj+Espace). L&apos;arrêt ne demande jamais de confirmation.</translation>
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
        <source>&amp;Reset layout</source>
        <translation>&amp;Réinitialiser la disposition</translation>
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
        <source>F12 or Ctrl+Shift+Space: STOP ALL
Teleop panel: W/A/S/D or arrows with the dead-man key held; Space or Esc: emergency stop
Site map: arrows pan, +/- zoom, F follow the selected machine
Ctrl+Shift+N: night palette
Ctrl+Shift+P: save a screenshot</source>
        <translation>F12 ou Ctrl+Maj+Espace : ARRÊT GÉNÉRAL
Téléopération : W/A/S/D ou flèches, touche homme mort maintenue ; Espace ou Échap : arrêt d&apos;urgence
Plan du site : flèches pour déplacer, +/- pour zoomer, F pour suivre la machine sélectionnée
Ctrl+Maj+N : palette de nuit
Ctrl+Maj+P : enregistrer une capture d&apos;écran</translation>
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
        <source>Operator Control Unit %1
JAUS (AS5669A/AS5710A, AEP-4818 IOP), ISO 23725 and OSYRIS on one console.</source>
        <translation>Poste de commande opérateur %1
JAUS (AS5669A/AS5710A, AEP-4818 IOP), ISO 23725 et OSYRIS sur une seule console.</translation>
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
        <source>Message from station %1: %2</source>
        <translation>Message de la station %1 : %2</translation>
    </message>
    <message>
        <source>OSYRIS has no remote stop: STOP message sent to every machine&apos;s display</source>
        <translation>OSYRIS n&apos;a pas d&apos;arrêt à distance : message STOP envoyé à l&apos;afficheur de chaque machine</translation>
    </message>
    <message>
        <source>not an OSYRIS machine: %1</source>
        <translation>pas une machine OSYRIS : %1</translation>
    </message>
    <message>
        <source>OSYRIS has no remote stop: STOP message sent to the machine displays</source>
        <translation>OSYRIS n&apos;a pas d&apos;arrêt à distance : message STOP envoyé aux afficheurs des machines</translation>
    </message>
    <message>
        <source>%1: OSYRIS machines carry no stop state to clear</source>
        <translation>%1 : les machines OSYRIS n&apos;ont pas d&apos;état d&apos;arrêt à lever</translation>
    </message>
    <message>
        <source>send_text: &quot;text&quot; must be 1 to 80 bytes (CmMsg)</source>
        <translation>send_text : &quot;text&quot; doit faire de 1 à 80 octets (CmMsg)</translation>
    </message>
    <message>
        <source>message sent to every station</source>
        <translation>message envoyé à toutes les stations</translation>
    </message>
    <message>
        <source>ping: &quot;idx&quot; must be a station index 0-253</source>
        <translation>ping : &quot;idx&quot; doit être un index de station 0-253</translation>
    </message>
    <message>
        <source>PING sent to station %1</source>
        <translation>PING envoyé à la station %1</translation>
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
</context>
<context>
    <name>ocu::SdlJoystickInput</name>
    <message>
        <source>No joystick</source>
        <translation>Aucun joystick</translation>
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
        <source>No JAUS section in the site configuration: no JAUS vehicles on this site.</source>
        <translation>Aucune section JAUS dans la configuration du site : aucun véhicule JAUS sur ce site.</translation>
    </message>
</context>
<context>
    <name>ocu::StopAllButton</name>
    <message>
        <source>STOP ALL</source>
        <translation>ARRÊT GÉNÉRAL</translation>
    </message>
    <message>
        <source>Stop every machine of every protocol (F12)</source>
        <translation>Arrêter toutes les machines de tous les protocoles (F12)</translation>
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
        <source>Keyboard: hold Shift (dead-man) and use W/A/S/D or the arrows.</source>
        <translation>Clavier : maintenir Maj (homme mort) et utiliser W/A/S/D ou les flèches.</translation>
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
</TS>

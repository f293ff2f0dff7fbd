"""Seed vocabularies of radio-report language.

These are *role* vocabularies, not category names: a cue such as "on fire" means "undesirable",
and is mapped at run time to whichever Information Space category of the knowledge base has
that role (or, if several do, to the one whose description is closest in MiniLM space). The
KB's glossary and category names/descriptions are added on top at run time, so a knowledge
base with other category names works without code changes.
"""

from __future__ import annotations

from lucifer.language.text import norm as _norm

UNDESIRABLE = "undesirable"
DESIRABLE = "desirable"
CRITICAL = "critical"

# phrase -> role. Multi-word phrases win over their parts (longest match).
ROLE_CUES: dict[str, str] = {}


def _keyed(words: set[str]) -> frozenset[str]:
    """A word set compared with token keys: each word with its key as well ("families" -> "familie")."""
    return frozenset(words) | {_norm(w) for w in words}


def _add(role: str, phrases: str) -> None:
    for p in phrases.split("|"):
        p = p.strip()
        if p:
            ROLE_CUES[p] = role


_add(UNDESIRABLE, """
branches still coming off|branches coming off|still coming off it|snapping loose|snapped loose|jammed shut|has jammed|
won't swing|wont swing|stuck open|stuck shut|
wasp nest|wasps' nest|wasps nest|hornets' nest|hornet's nest|
glass falling|glass falling off|glass coming down|water coming out of|water pouring out of|water gushing out of|
we're holed|we are holed|been holed|is holed|holed on|holed below|
come off its pegs|off its pegs|pulled its pegs|blowing about|blowing around|
car's turned over|van's turned over|has turned over|turned over on|flipped over on|
stones falling|stones are falling|are falling from the|falling from the walls|masonry falling|
steam blow out|steam blowout|steam blow-out|
nobody go in there|no one go in there|
it's been hit|it has been hit|been struck by lightning|
branch down|big branch down|branch has come down|branch came down|limb down|
load's shifted|load has shifted|load shifted|loads shifted|shifted load|shifted its load|load's slipped|load has slipped|
gone live|gone live again|is live again|went live again|is live|s live|are live|still live|
have come off the|has come off the|running brown|properly under|slid right across|slid across the|come clean off|roof's come off|roof has come off|roof came off|broken straight through its bank|broken through its bank|broken through the bank|is also water|scouring the bank|scouring the bank away|metre above normal|metres above normal|foot above normal|feet above normal|taking the fences with it|up to his windowsills|up to her windowsills|up to their windowsills|up to the windowsills|up to the sills|water is already up to|water's already up to|water is up to the|water's up to the|dropped and split|split in two|split in half|slates have come off|shed half its|has shed half its|
been torn off|torn away|
have toppled|has toppled|toppled over|toppling|has split down|have split down|split down the seam|split open|toppling over|fell down|has fallen down|toppled all over|it's a wreck|its a wreck|a complete wreck|a total wreck|
back wall in|side wall in|front wall in|gable wall in|pushed the wall in|pushed its wall in|
has half gone into the water|s half gone into the water|half gone into the river|
water has gone over|water's gone over|gone over both ends|is roaring|brown and boiling|over the sill|stopper|
half under|are afloat|is afloat|afloat and|drifting into|jammed against|starting to bow|stones pinging off|
thick black stuff|black plumes|plumes of|plume of|exposed conductors|treat as energised|energised|
fractured main|fractured gas main|lel|percent lel|stinging smell|chemically smell|chemical smell|eyes stream|
eyes are streaming|eyes streaming|vapour's that strong|hanging by a thread|hanging by one bolt|hanging by one cable|steam everywhere|relief valve blowing|valve blowing|relief valve lifting|relief valve has lifted|icy|really icy|very icy|lost a column|lost a pillar|lost a support|spraying everywhere|oil everywhere|spraying all over|going for people|dogs loose|loose dogs|dog loose|loose dog|a release from|gas release|chemical release|ammonia release|is full of steam|s full of steam|filled with steam|spitting boiling water|boiling water everywhere|hanging by a cable|hanging by one wire|could fall any minute|could fall at any minute|could come down any minute|could come down at any minute|suspicious package|suspect package|suspicious bag|unattended bag|suspicious item|hanging off its brackets|
hanging off its bracket|swinging in the wind|oak down|big tree down|branches down|write-off|oven's gone up|
s a lake|is a lake|like a lake|turned into a lake|come clean over|gone over the top|come over the top|overtopped|
dropped into the river|dropped into the water|gone into the river|bridge has gone|bridge s gone|
going up like|tins going up|bottles going up|roof is about to go|roof s about to go|wall is about to go|about to give way|going to give way|could go any minute|
water's lapping|water lapping|lapping at the doors|full to the rafters|full of water|filled with water|filling with water|filling up with water|
groaning and tilting|is tilting|s tilting|tilting towards|tilting badly|about to topple|going to topple|come crashing down|came crashing down|crashing down|crashed down|crashed through|handrail's gone|handrail has gone|railings have gone|railing's gone|bridge is shaking|it's shaking|s shaking|
water all over it|water all over the|water's got into|water has got into|water got into|river's coming in|river is coming in|river coming in|water is coming in|water's coming in|water coming in|water is getting in|water's getting in|water pouring in|
walkway s twisting|is twisting|s twisting|bolts pinging|going to go|s going to go|
fire|fires|on fire|burning|burnt|burned|burned out|burnt out|blaze|blazing|ablaze|flames|flame|in flames|
engulfed|inferno|smoke|smoking|smoky|smoke everywhere|thick smoke|fumes|toxic fumes|
gas|gas leak|leaking gas|smell of gas|smells of gas|leak|leaking|explosion|exploded|explosive|blast|
collapse|collapsed|collapsing|caved in|cave in|cave-in|caving in|fell in|falling down|come down|came down|
rubble|debris|unstable|crumbling|cracked|cracking|sagging|structural damage|structurally unsafe|
flood|floods|flooded|flooding|underwater|under water|water rising|rising water|submerged|knee deep|
strong current|fierce current|fast current|swift current|rip current|undertow|current's ripping|current is ripping|
current ripping|fast flowing water|fast-flowing water|
live wire|live wires|power line down|power lines down|downed lines|sparking|sparks|electrified|arcing|
chemical|chemicals|chlorine|chlorine gas|toxic|spill|spilled|spilt|hazmat|contaminated|radiation|asbestos|
dangerous|danger|unsafe|hazard|hazardous|hazards|threat|no go|no-go|off limits|do not enter|keep out|stay away|
avoid|blocked|impassable|sinkhole|landslide|mudslide|hot spot|hotspot|burning debris|roof down|roof collapsed|
gunfire|shooter|armed|looters|riot|on fire again|reignited|spreading|spread|unsound|structurally unsound|
compromised|unstable structure|partially collapsed|caving|smouldering|smoldering|charred|gutted|
alight|well alight|fully involved|going up in flames|gone up in flames|bowing|buckling|wall's bowing|could go any second|
about to collapse|coming down|falling in|roof has come in|roof's come in|roof came in|ceiling's down|ceiling down|
ceiling has come in|ceiling's come in|ceiling collapsed|roof's still moving|roof is still moving|roof's moving|
roof is moving|keep clear|stay clear|keep off it|keep off there|red for entry|sparks everywhere|
stinks of gas|reeks of gas|reeking of gas|reeking of|fuel leak|oil spill|overtopping|burst its banks|breached|
landslip|slipping|given way|gave way|has given way|come away|came away|taking on water|taking water|
flashover|flashover risk|backdraft|backdraft risk|spongy|floor's spongy|leaning|buckled|buckling|ruptured|
gas main|water's up|water up to|up to the windowsills|smoke logged|smoke logging|heavy fire|fire showing|
fully developed fire|ammonia|ammonia leak|asbestos|unstable chimney|hazmat incident|arcing|
fuel pouring|pouring fuel|roof's going|roof is going|everyone out|get everyone out|evacuate|evacuating|
smell of gas|strong smell of gas|gas smell|water damage|waist deep|chest deep|electrical hazard|exposed wiring|
hot zone|exclusion zone|inner cordon|wall down|walls down|fence is down|fence's down|fences are down|fence is flat|roof's in|roof is in|roof's gone|roof has gone|
roof's off|shedding bricks|shedding slates|unstable masonry|masonry falling|falling masonry|flooded out|mud slide|
slumping|waterlogged|water logged|halfway up|burst main|burst pipe|pipe burst|pipe's burst|pipes bursting|pipes are bursting|pipes have burst|steam line burst|steam line has burst|burst steam line|steam pipe burst|burst steam pipe|steam leak|live steam|water everywhere|
bowing out|bowing|bulging|bulge|water coming over|coming over the|ripping through|smoke-logged|fully alight|jammed open|stuck open|won't close|wont close|will not close|not closing|won't shut|wont shut|not shutting|
floor's gone|floor has gone|floor's gone through|gone through the floor|sinking|subsiding|subsidence|cracked right across|
a crack|crack right across|cracks|venting|hissing|gas bottles|leaking fuel|diesel slick|slick|fuel slick|
jammed shut|jammed|locked|padlocked|chained|chained shut|can't get in|cannot get in|can't get into|cannot get into|
can't get through|cannot get through|can't get round|cannot get round|can't get past|cannot get past|can't get along|cannot get along|can't get at|can't be got at|
no access|no vehicle access|no way in|no way through|no way onto|no way out|inaccessible|not passable|
no through route|piled across|right across it|lying across|come down across|came down across|
blocking|blocks the|blocked off|cordoned off|out of bounds|out-of-bounds|shed its load|gridlocked|choked with|full of parked cars|
filled right up|can't reach|cannot reach|unable to reach|unable to get in|can't access|cannot access|washed away|
foot of water|feet of water|under a foot of water|ankle deep|water coming up|water coming in|water's coming in|coming in under the door|coming in under the doors|
petrol all over|fuel all over|diesel all over|oil all over|petrol everywhere|diesel everywhere|fuel everywhere|
petrol leak|diesel leak|fuel spill|petrol spill|diesel spill|exploding|explode|could explode|
wall's fallen|wall has fallen|walls have fallen|roof's fallen|roof has fallen|ceiling's fallen|ceiling has fallen|
chimney's fallen|chimney has fallen|fallen masonry|fallen tree|tree's fallen|tree has fallen|tree down|trees down|
flattened|smashed in|swaying|fallen in|slipped in|smashed|is going up|s going up|still going up|going up properly|is catching|catching too|caught too|
no-go|no go|no-go area|no go area|no-go areas|no go areas|a no-go|a no go|a torrent|raging torrent|like a torrent|
up to the gutters|is up to the|right up to the|up to the windows|up to the second-floor windows|
lifted clean off|
uprooted|windthrown|windthrow|blown down|
blown into the crowd|blew into the crowd|treacherous|stones flying|flying stones|debris flying|flying debris|thick with vapour|thick with fumes|thick with gas|full of vapour|thick with vapor|
snake|snakes|a snake|venomous snake|adder|adders|viper|vipers|rattlesnake|rattlesnakes|
loose cattle|loose cows|loose bull|bull is loose|bull's loose|bull s loose|loose livestock|cattle loose|cattle are loose|cattle have got out|cows have got out|stampede|stampeding|
could drop any second|could drop any minute|could drop at any moment|
over topping|is over topping|lost its brakes|lost his brakes|lost her brakes|no brakes|brakes have gone|brakes failed|
lines snapped|line snapped|line's snapped|cable snapped|cable's snapped|cables snapped|rope snapped|rope's snapped|whipping around|whipping about|whipping round|
""".replace("\n", ""))

_add(DESIRABLE, """
dry and open|open and dry|it's dry there|its dry there|it's dry in there|dry in there|dry over there|
turned the waiting room over|drying them off|drying people off|cups of tea|camp beds|the dry place|a dry place|
put the kettle on|kettle's on|heating's up|heating is on|making sandwiches|ticking names off|ticking people off|
got everyone gathered|everyone gathered|everybody gathered|fed and counted|being fed|being counted|reception point|roll call|warm room|warm up|
get warm|a warm and a brew|teas going|tea going|ticked off a list|being ticked off|being registered|registered and fed|
being looked after|looked after there|marshalling there|are marshalling|taking in anyone|taking in everyone|
handing out blankets|blankets and brews|blankets and tea|welfare point|we're gathering|we are gathering|gathering everyone|gathering everybody|gathering the visitors|gathering the residents|
gathering the evacuees|gathering people in|to cool down|to cool off|nice and cool|cool and shady|shady and cool|in the shade|it's shady|it s shady|cold drinks|
air conditioned|air-conditioned|air con|
room for maybe|room for about|room for another|got room for|have room for|plenty of room|room for more|room for a few more|room for three or four more|room for plenty more|dry and solid|the walls held|walls have held|the roof held|roof has held|waiting safely|sheltering safely|safely inside|blankets out|dry and warm|warm and dry|put the families in there|put everyone in there|
put them in there|put people in there|
air's clean|air is clean|the air is clean|clean air|air's okay|air is okay|air's ok|air is ok|air's fine|air is fine|
air is good|air's good|good spot|a good spot|good place|a good place|
muster|mustering|we'll muster|we're mustering|mustering everyone|mustering the staff|
safe|safe zone|safe area|safe to enter|safe to shelter|safe to pass|safe passage|safe route|
clear|all clear|cleared|clear now|secure|secured|secure now|sheltering|shelter|shelter point|
evacuation point|evacuation centre|evacuation center|rally point|rendezvous point|
staging point|triage|triage area|first aid post|first aid station|aid station|relief centre|relief center|
passable|good to go|accessible|open route|route open|checked and safe|stable|casualty clearing station|
clearing station|welfare centre|welfare center|rest centre|rest center|green for entry|safe for entry|first aid point|
rvp|designated rvp|searched and signed off|use|use it|use it for shelter|signed off|cleared and marked|safe haven|casualty collection point|
structurally sound|intact|usable|refuge|sanctuary|holding area|collection point|gathering point|cold zone|
welfare point|holding point|muster point|muster station|assembly point|assembly area|evacuee assembly area|
reception centre|reception center|rest center|high ground|taking evacuees|taking in evacuees|open as a rest centre|
opened as a rest centre|safe ground|dry and safe|bone dry|warming centre|warm and dry|sheltering there|
meeting point|the meeting point|empty and checked|checked and empty|evacuated and checked|searched and clear|
is open|s open|are open|still open|open again|reopened|open and usable|open for landing|
decon point|decon area|decon tent|decontamination point|where we're putting everyone|putting everyone|high and dry|well above the water|high above the water|well above the flood|well clear of the water|holding people in|holding everyone in|holding them in there|holding people there|we're holding people|place of safety|a place of safety|cots and blankets|put out cots|can shelter there|can shelter here|people can shelter|can come and wait|can wait there|can wait in there|can wait here|been walked and checked|walked and checked|opened up for|opened its doors|
fine to walk through|fine to walk on|fine to cross|okay to walk through|ok to walk through|fine to pass through|
fine for overflow|taking in families|taking in people|taking people in|can take people|we can take people|
people are gathering there|people gathering there|everyone's gathering there|gathering there|taking in residents|
taking in the evacuees|taking families|taking the overflow|taking overflow|taking the overspill|evac point|evac points|evac centre|evac center|evacuation points|
anyone cold can go|stove going|stove is going|stove's going|stove lit|stove's lit|stoves going|got the stove going|has heat and power|has power and heat|heaters on|tea on|there's tea on|kettle's on|kettle on|warm, dry|can come here|got the heaters on|heating on|got the heating on|holding everyone|where we're holding|can go up there|soup on|hot food|hot drinks|warm drinks|rest stop|wait inside safely|letting people wait inside|letting people shelter|letting people in to shelter|
where we're sending everyone|where we're sending people|where we're sending them|where we're taking everyone|
where we're taking people|where we're putting people|where we're putting everyone|where everyone's going|
where everyone is going|putting people there|putting people in there|putting everyone there|moving people there|send people there|
sending people there|moving evacuees there|send them there|
undamaged|casualty clearing point|casualty clearing post|casualty clearing centre|clearing point|
treatment area|treatment centre|treatment center|treatment point|treatment tent|stand-down area|stand down area|
stand-down point|designated holding area|
rest point|rest area|is shaded|shaded and checked|got shade and water|has shade and water|our dry spot|a dry spot|the dry spot|letting people in|free tea|free food|bedding down|bedded down|been taken in at|been taken in by|taken in at|feeding station|feeding centre|rendezvous|rendezvous with|
can stay put|can stay where they are|stay put in there|no risk there|is no risk|s no risk|wait it out|wait it out in|sit it out in|safe to stay|
""".replace("\n", ""))

_add(DESIRABLE, "can stay in|they can stay|as long as they need|warm n dry|we're sound|we are sound|all sound here|"
               "with a brew|having a brew|upstairs is dry|is dry though|folk off the shore|let us all in|let us in|")
_add(DESIRABLE, "open, dry|open dry|crew room open|got the crew room open|dry and sound|welcome to stay|are welcome to stay|settled in the pews|warm spot|a warm spot|"
               "having soup|opened it up as|opened up as a|")
_add(DESIRABLE, "welcome to wait|are welcome to wait|came through without a scratch|come through without a scratch|"
               "well above the tide line|above the tide line|we'll wait there|"
               "power's on in there|power is on in there|you can plug|sheltered enough|still above the line|"
               "come and fill up there|fill up there|can fill up there|can fill up from|fill up from it|"
               "assembly spot|where everyone's gathering|where everybody's gathering|nothing to fall on anyone|"
               "dry and cool|can stand on it|can all stand on it|safe to stand on|fine to stand on|")
# ("the staff say people are welcome to wait inside", "the bottle cellar is dry and cool", "Wharf's solid, crews can
# stand on it", "I've landed six kids on Heron Rock, it's well above the tide line", "the genny shed's working, power's
# on in there", "the cricket field's still above the line")
_add(DESIRABLE, "for everybody to go to|for everyone to go to|for people to go to|for folk to go to")
_add(DESIRABLE, "the cool spot|a cool spot|cool spot now|cooling spot|cooling point|cooling station|cooling centre|"
               "cooling center")  # ("the camp the bowser waters is the cool spot now": out of the heat)
_add(DESIRABLE, "has power and heating|got power and heating|power and heating on|can come in here|"
               "anybody can come in|anyone can come in|everyone can come in|can all come in")
# people sent or taken to a place ("we're sending families there", "so send the evacuees in there")
_add(DESIRABLE, "|".join(f"{verb} {who} {where}"
                         for verb in ("send", "sending", "take", "taking", "bring", "bringing", "move", "moving",
                                      "direct", "directing")
                         for who in ("families", "everyone", "everybody", "evacuees", "residents", "people", "folk",
                                     "the families", "the evacuees", "the residents", "the kids", "the children")
                         for where in ("there", "in there", "up there", "over there")))

_add(CRITICAL, "|".join(f"{aux} {verb} in" for aux in ("haven't", "havent", "hasn't", "hasnt", "have not", "has not",
                                                           "not", "never")
                         for verb in ("radioed", "checked", "reported")))  # "haven't radioed in for forty minutes"
# ("We've pulled a man out of the coffee shop, he's breathing"; "one of the engineers still out on it")
_add(CRITICAL, "|".join(f"pulled {who} out of" for who in ("a man", "a woman", "someone", "somebody", "a child", "a kid",
                                                             "him", "her", "a lad", "a girl", "a boy")))
_add(CRITICAL, "still out on it|still out on the|stuck out on it|still stuck out on")
_add(CRITICAL, "has broken his|has broken their|have broken his|'s broken his|have broken leg|has broken leg|"
               "have broken arm|has broken arm|have broken hip|has broken hip|have broken a|has broken a")
_add(CRITICAL, "he fall down|she fall down|he not wake up|she not wake up|he not waking|she not waking|"
               "through his hand|through her hand|hook through his|hook through her|visitors stung|people stung|"
               "been stung|got stung|were stung|stung badly|badly stung")
_add(CRITICAL, "sick in bed|lady sick|man sick|she drank it|he drank it|drank diesel|swallowed diesel")
_add(CRITICAL, "wandering and confused|found wandering|confused and wandering|wandering confused")
_add(CRITICAL, "still aboard|person still aboard|one person still aboard|still on the boat")
_add(CRITICAL, "kid lost|child lost|a lost kid|boy lost|girl lost|crew are still down there|crew still down there|are still down there|still trapped down there")
_add(CRITICAL, "coughing up smoke|coughing smoke|coughing up black")  # (a symptom, not smoke at the place)
_add(CRITICAL, "breathing trouble|trouble breathing|needing oxygen|short of breath")
_add(CRITICAL, "need the rescue boat|needs the rescue boat|need a rescue boat|need the lifeboat|needs the lifeboat")
# ("my son walked out to the rock pile and he's not back"; "says he can't feel his left leg")
_add(CRITICAL, "he's going under|hes going under|she's going under|shes going under|they're going under|"
               "theyre going under|")  # ("a kid gone in off the end of the landing stages ... he's going under")
_add(CRITICAL, "been burned in|been burnt in|been badly burned|been badly burnt|got burned|got burnt|")
_add(CRITICAL, "down on the floor in there|lad down on the floor|lads down on the floor|man down on the floor|"
               "one of them down on the floor|")  # ("there's one of the lamp lads down on the floor in there")
_add(CRITICAL, "he's not back|she's not back|they're not back|he isn't back|she isn't back|they aren't back|"
               "hes not back|shes not back|theyre not back|not back yet|still not back|"
               "can't feel his|can't feel her|cant feel his|cant feel her|cannot feel his|cannot feel her|"
               "can't feel my|cant feel my|cannot feel my")
_add(CRITICAL, "didn't come back|didnt come back|did not come back|haven't come back|havent come back|"
               "can't see them anywhere|cant see them anywhere|can't find them anywhere|cant find them anywhere|"
               "can't see him anywhere|can't see her anywhere|can't find him anywhere|can't find her anywhere")
_add(CRITICAL, """
folk up on the roofs|people up on the roofs|got folk up on the roofs|got people up on the roofs|up on their roofs|
can't pull himself out|can't pull herself out|cant pull himself out|cant pull herself out|up to his chest|up to her chest|
up to his waist|up to her waist|up to his neck|up to her neck|can't get her door open|can't get his door open|
cant get her door open|cant get his door open|can't get the door open|
can't get off|cant get off|won't answer|wont answer|can't open the doors|cant open the doors|never came back|
hasn't come back|hasnt come back|up to his knees|up to her knees|head bleed|query head bleed|can't feel his legs|can't feel her legs|cant feel his legs|cant feel her legs|
can't feel their legs|come off the ladder|came off the ladder|came off a ladder|come off a ladder|fell off a ladder|fallen off a ladder|fallen off the ladder|fell off the ladder|gcs|
got it in his eyes|got it in her eyes|in his eyes|in her eyes|very muddled|she's muddled|he's muddled|dehydrated|hasn't had a drink|hasnt had a drink|not had a drink|drowsy and confused|clammy|
without his insulin|without her insulin|without their insulin|without his medication|without her medication|
without their medication|without his tablets|without her tablets|shaking and sweating|stuck between floors|
stuck between two floors|last seen going into|last seen heading into|last seen at|last seen in|last seen near|soaked to the skin|shivering that hard|can barely talk|been dragged|being dragged|got dragged|dragged along by|cannot speak|can't speak|cant speak|can not speak|can't talk|cannot talk|he is very cold|she is very cold|he's very cold|she's very cold|is freezing cold|wants an ambulance|needs an ambulance|people are still in|people still in|are still trapped|waving a torch|waving a light|up on its roof|up on the car roof|on top of the car|on the roof of the car|
burnt both his|burnt both her|burned both his|burned both her|burnt his arms|burnt her arms|burned his arms|
burned her arms|burnt his hands|burnt her hands|burned his hands|burned her hands|cannot be reached|can't be reached|
cant be reached|request lift|requesting a lift|need lifting off|needs lifting off|uses a frame|uses a walking frame|
uses a zimmer|on a zimmer|can't get hold of my|cant get hold of my|refused to leave|has refused to leave|refused to come out|sat on the roof|sat on his roof|sat on her roof|
sat on their roof|need the boat|need a boat|needs a boat|has slipped on|slipped on the|ankle gone|ankle's gone|knee gone|knee's gone|done his ankle|done her ankle|done his knee|done her knee|can't lift him|can't lift her|cannot lift him|cannot lift her|cant lift him|cant lift her|can't get him up|
can't get her up|cannot get him up|cannot get her up|won't come out|wont come out|won't come down|wont come down|refusing to come down|refuses to come down|refusing to come out|refuses to come out|won't leave|wont leave|refusing to leave|refuses to leave|
swept off his feet|swept off her feet|swept off their feet|hanging on to|hanging onto|
stretcher needed|need a stretcher|needs a stretcher|stretcher required|stretcher to|
need to get them out|need hands to get them out|to get them out|can't get them out|cannot get them out|
all cut up|badly cut up|cut to pieces|holding his head|holding her head|clutching his head|clutching her head|come staggering out|came staggering out|staggered out|staggering out|
can't get her out|cannot get her out|can't get him out|cannot get him out|can't get her free|can't get him free|
she's under it|he's under it|they're under it|she's underneath it|he's underneath it|
toddlers inside|children inside|kids inside|still has children inside|
ankle is broken|ankle's broken|wrist is broken|wrist's broken|hip is broken|leg's broken|arm's broken|
can't put any weight|cannot put any weight|can't put weight|can't weight bear|cannot weight bear|heat exhaustion|
heatstroke|heat stroke|
went into labour|gone into labour|in labour|needs a midwife|sitting on the roof|sitting on roofs|sitting on caravan roofs|
on their roofs|lady fallen|old lady fallen|woman fallen|man fallen|old man fallen|someone's fallen|she's fallen|he's fallen|
need carrying out|needs carrying out|by stretcher|stretcher case|one's collapsed|one has collapsed|one of them's collapsed|one of them has collapsed|coming out coughing|she's still up there|he's still up there|they're still up there|still up there|doesn't walk well|can't walk well|arm deformed|leg deformed|query spinal|spinal injury|suspected fracture|query fracture|fractured|lady gone down|
woman gone down|man gone down|bloke gone down|someone gone down|somebody gone down|person gone down|gone very grey|gone grey|gone a funny colour|slid off her chair|slid off his chair|slumped|feeling unwell|feeling ill|
feeling sick|taken ill|been taken ill|can't manage the stairs|cannot manage the stairs|carry chair|with cuts|cuts from|cuts to his|cuts to her|cuts to their|cuts and bruises|nasty cuts|bad cuts|with a cut|a bad cut|a nasty cut|a deep cut|really bad cut|
scalded|scalds|scalding burns|badly scalded|with scalds|
trapped|trapped inside|stuck|stuck inside|pinned|pinned down|buried|injured|injuries|injury|hurt|
wounded|bleeding|unconscious|unresponsive|not breathing|not moving|cardiac arrest|cardiac|a cardiac thing|heart thing|need the ambulance|needs the ambulance|broken leg|broken arm|
casualty|casualties|victim|victims|survivor|survivors|patient|patients|
needs help|need help|needs rescue|need rescue|needs rescuing|need rescuing|calling for help|crying for help|
cries for help|screaming|shouting for help|banging|knocking|someone inside|people inside|person inside|
kids inside|children inside|family inside|elderly inside|residents inside|
missing person|missing persons|missing|soaked and shaking|dislocated shoulder|dislocated his shoulder|dislocated her shoulder|dislocated his knee|dislocated her knee|rider lying|riders lying|lying injured|gashed his arm|gashed her arm|gashed his leg|gashed her leg|gashed his hand|gashed her hand|gashed his head|gashed her head|soaked through and shivering|soaked and shivering|wet and shivering|shivering|needs a blanket|needs checking over|needs a check over|soaking wet and shaking|wet and shaking|shaking badly|shivering badly|can't stop shivering|been bitten|a snake bit|the snake bit|snake bit|snake bite|snakebite|bit one of|needs antivenom|antivenom|stab wound|stab wounds|knife wound|nasty bite|a bad bite|a bite on his|a bite on her|bite on the hand|got bitten|was bitten|got bit by|was bit by|been bit by|bitten by|bitten on the|man down|person down|woman down|needs the doctor|need the doctor|needs the medic|needs a medic|workers down|worker down|men down|pickers down|people down|men down|both burnt|both burned|men burned|men burnt|man burned|man burnt|people burned|people burnt|women burned|woman burned|lads burned|crew burned|crew burnt|cut up bad|cut up badly|badly cut up|
medical emergency|medical help|needs a medic|needs medic|needs an ambulance|needs evacuation|
can't get out|cannot get out|can't move|cannot move|burns victim|overcome by smoke|
stranded|cut off|trapped people|trapped persons|people trapped|someone trapped|somebody trapped|
hypothermic|going hypo|gone hypo|hypoglycaemic|hypoglycemic|drowning|bleeding out|critical condition|in shock|lost consciousness|passed out|fainted|keeled over|keels over|has keeled over|collapsed inside|
pinned under debris|pinned under rubble|trapped under debris|trapped under rubble|buried under rubble|buried under debris|
trapped in rubble|under the rubble|needs medics|need medics|medics to the|paramedics to the|needs a doctor|requires evacuation|unaccounted for|
people still inside|still inside|someone still inside|can't get back|cannot get back|can't get back to shore|water all round him|water all round her|water all round them|water all round us|water all around him|water all around them|on the roof with water|still in the cab|still in his cab|still in her cab|driver still in|people stuck|people stuck inside|with people inside|
twisted ankle|a twisted ankle|a twisted knee|twisted knee|twisted her ankle|twisted his ankle|twisted their ankle|twisted their knee|twisted her knee|twisted his knee|twisted my knee|twisted my ankle|hurt their knee|hurt her knee|hurt his knee|can't find my mummy|can't find my mum|can't find my mommy|can't find my mom|can't find my dad|can't find my daddy|can't find my parents|lost my mummy|lost my mum|lost my mommy|lost my mom|lost my dad|lost my parents|gone over on her ankle|gone over on his ankle|went over on her ankle|went over on his ankle|turned her ankle|turned his ankle|rolled her ankle|rolled his ankle|sprained ankle|broken ankle|is injure|he injure|she injure|he not move|she not move|not move|cut head|a cut head|bleeding head|needs a paramedic|need a paramedic|needs paramedics|deep cut|bad cut|can't find his mum|can't find her mum|can't find his dad|can't find her dad|can't find their parents|
people under it|people under there|someone under it|somebody under it|people underneath|breathing problems|breathing difficulties|difficulty breathing|struggling to breathe|can't breathe|cannot breathe|
man collapsed|woman collapsed|person collapsed|someone collapsed|somebody collapsed|he collapsed|she collapsed|
is choking|was choking|started choking|he's choking|she's choking|
needs oxygen|need oxygen|having a heart attack|heart attack|seizure|having a seizure|can't breathe|cannot breathe|
asthma attack|asthma attacks|an asthma attack|having an asthma attack|shut in|locked in|
stuck on the roof|stranded on the roof|on the roof waiting|waving from|trapped upstairs|trapped on|
can't get up|cannot get up|can't get out|can't free|cannot free|waving for help|yelling for help|for help|
can't climb out|cannot climb out|can't climb back up|cannot climb back up|can't climb back out|can't get back out|
can't get back up|
still on board|riders still on board|done his back in|done her back in|done his back|done her back|hurt his back|hurt her back|put his back out|put her back out|riders still on it|people still on it|kids still on it|children still on it|passengers still on it|skiers still on it|stuck at the top|stranded at the top|leg is broken|arm is broken|broken leg|broken arm|broken hip|busted leg|busted arm|busted ankle|busted wrist|broke his leg|broke her leg|broke his arm|
stung all over|been stung|badly stung|stung by bees|stung by a bee|broke her arm|broke his hip|broke her hip|broken ankle|broke his ankle|broke her ankle|burnt arm|burnt hand|burned arm|burned hand|burnt leg|burnt face|burned face|with burns|burns to his|
burns to her|burnt his|burnt her|burned his|burned her|cracked his head|cracked her head|cracked their head|cracked his skull|cracked her skull|banged his head|
banged her head|hit his head|hit her head|split his head|split her head|cut his hand|cut her hand|cut his head|
cut her head|cut his leg|cut her leg|head wound|head injury|hurt bad|badly hurt|walking wounded|screaming inside|kids screaming|someone in the water|people have gone into the water|have gone into the water|has gone into the water|gone in the water|went into the water|
smoke inhalation|smoke casualty|smoke casualties|persons reported|person reported|p1|p2|p3|p1s|p2s|p1 patient|p2 patient|priority one|cpr|
cpr in progress|a body|body|bodies|non ambulatory|non-ambulatory|overcome|officer down|firefighter down|
occupants unaccounted for|entrapment|trapped occupant|casualty pinned|
person in the water|in the water|unaccounted for|still inside|not responding|no pulse|crush injury|burns|
piw|medic needed|medics needed|medic required|need a medic|need medics|paramedic needed|paramedics needed|
ambulance needed|ambulance required|need an ambulance|send an ambulance|needs medical attention|medical attention|chest pain|chest pains|in difficulty|in difficulties|not accounted for|hasn't been accounted for|has not been accounted for|haven't been accounted for|have not been accounted for|not been accounted for|clinging to|clinging on|broken hip|
broken ankle|broken wrist|head injury|fractured|fracture|crushed|crushed foot|crushed leg|concussion|
can hear someone|can hear her|can hear him|can hear them|can hear voices|hear someone|hear her|hear him|
hear voices|waving at us|waving to us|calling from|shouting from|trapped under|under the timbers|overdue|
gone under|went under|capsized|has capsized|not come up|hasn't come up|hasnt come up|not come back up|not surfaced|hasn't surfaced|swept away by|has been swept into|have been swept into|was swept into|were swept into|got swept into|in the river|in the sea|hypothermia|casualty recovered|recovered from the water|swept away|
still in there|still in there somewhere|still got children upstairs|still got kids upstairs|still got people upstairs|children still upstairs|kids still upstairs|people still upstairs|can't find him|can't find her|can't find them|cannot find him|cannot find my son|cannot find my daughter|cannot find my child|cannot find my boy|cannot find my girl|cannot find my kid|cannot find my little boy|cannot find my little girl|can't find my son|can't find my daughter|can't find my child|can't find my boy|can't find my girl|can't find my kid|can't find my little boy|can't find my little girl|cant find my son|cant find my daughter|cant find my child|cant find my boy|cant find my girl|cant find my kid|cant find my little boy|cant find my little girl|
people coughing|few of them collapsed|some of them collapsed|collapsed on the floor|
live find|a live find|indicating a find|can't get down|cannot get down|can't get downstairs|cut his arm|cut her arm|
cut his hand|cut his head|cut her head|badly cut|in trouble|in difficulty|in difficulties|has fever|has a fever|has a high fever|got a fever|need doctor|needs doctor|need a doctor|needs a doctor|cut very bad|cut very badly|cut really bad|cut bad|cut from the glass|cut by the glass|cut by flying glass|can't get back down|cannot get back down|can't get back out|can't get up the step|cannot get up the step|bleeding heavily|can't get the doors open|can't get the door open|
cannot stand up|can't stand up|can't walk|cannot walk|fell over|has fallen over|he fell|she fell|
he fall|she fall|frostbite|frostbitten|frostbite case|is lost|he's lost|she's lost|got lost|lost child|lost kid|gone missing|has gone missing|is sick|are sick|sick inside|feeling sick|being sick|vomiting|throwing up|taken ill|feeling ill|
cut by flying glass|cut by glass|cut by falling glass|hit by flying glass|hit by debris|hit by falling debris|
broken his hip|broken her hip|broken his leg|broken her leg|broken his arm|broken her arm|broke his leg|broke her leg|
waving out the window|waving out of the window|waving out of windows|waving from the window|
not come out|hasn't come out|has not come out|haven't come out|havent come out|didn't come out|never came out|nobody has seen him come out|nobody has seen her come out|no one has seen him come out|no one has seen her come out|no one's seen him come out|no one's seen her come out|nobody's seen them come out|nobody has seen them come out|no one's seen them come out|no one has seen them come out|nobody's seen him come out|nobody's seen her come out|nobody saw them come out|not come back out|hasn't come back out|
been knocked down|got knocked down|been knocked over|got knocked over|was knocked over|been kicked|got kicked|was kicked|kicked by a|kicked by the|been trodden on|got trodden on|was trodden on|trodden on by|knocked off her bike|knocked off his bike|was knocked down|knocked over by|been hit by|was hit by|got hit by|hit by a|
struck by a|been run over|was run over|got run over|not conscious|isn't conscious|is not conscious|
send a boat|please send a boat|need a boat|send help|please send help|come and get us|come get us|get us out|
please come|please hurry|please help us|fire fighter down|fireman down|fire fighter injured|not answering|isn't answering|he's not answering|she's not answering|
just lying there|lying there|lying on the floor|lying on the ground|fell off|fallen off|took a fall|fallen down a|fell down a|fallen down the|fell down the|
out cold|knocked out|knocked unconscious|electrocuted|got a shock|got a belt|needs lifting|needs lifting off|
needs winching|needs winching off|heat signature|heat signatures|thermal signature|under the bricks|
under the wreckage|under the masonry|is under it|s under it|are under it|still under it|
gashed leg|gashed arm|gashed head|gashed his leg|gashed her leg|badly gashed|someone lying|somebody lying|a man lying|a woman lying|a person lying|a child lying|lying at the bottom of|lying injured|lying unconscious|haven't come out|havent come out|have not come out|can't come down|cannot come down|can't come out|cannot come out|is underneath it|s underneath it|are underneath it|haven't come back|hasn't come back|not come back down|not come back yet|gash on his head|gash on her head|a gash on|blood all down his face|blood all down her face|blood down his face|blood down her face|bleeding from the head|bleed from the head|lying motionless|motionless|she's not talking|he's not talking|not talking to us|lad fitting|he's fitting|she's fitting|someone fitting|man fitting|having a fit|he's seizing|she's seizing|ligature|ligatured|found hanging|prisoner hanging|someone hanging|lad hanging|man hanging|hostage|hostages|taken hostage|held hostage|officer slashed|been slashed|was slashed|stabbed|been stabbed|i've fallen|i have fallen|i fell|we've fallen|can't get myself up|cannot get myself up|can't get herself up|can't get himself up|
coughing|coughing badly|coughing their lungs up|on oxygen|broken collarbone|can't reach her|can't reach him|can't reach them|
cannot reach her|cannot reach him|cannot reach them|can't get hold of her|can't get hold of him|can't get hold of them|
not answered since|hasn't answered since|haven't heard from her|haven't heard from him|haven't heard from them|
nothing since|no word from her|no word from him|no word from them|lost contact with|
had a fall|has had a fall|taken a fall|had a nasty fall|tripped over|tripped and fell|tripped on|slipped and fell|
slipped over|slipped on|cut by|been cut|needs evacuating|need evacuating|needs moving|need moving|needs moving out|
need moving out|needs getting out|need getting out|needs carrying out|need carrying out|hit by falling|
hit by a falling|struck by falling|struck by a falling|overdosed|taken an overdose|
snapped his leg|snapped her leg|snapped his arm|snapped her arm|snapped his ankle|snapped her ankle|snapped his wrist|snapped her wrist|
knock to the head|knock on the head|taken a knock|took a knock|blow to the head|gone dizzy|went dizzy|feeling dizzy|come over dizzy|
can't get his wheelchair|can't get her wheelchair|cannot get his wheelchair|cannot get her wheelchair|can't get up the stairs|can't manage the stairs|
there's folk in|theres folk in|folk in them|folk in there|people in them|there's people in|theres people in|folk still in|
gone in off the|someone's gone in|somebody's gone in|went in off the|gone in the water|went in the water|
gone in after|went in after|jumped in after|gone in after a dog|went in after a dog|we're pulling him out|we're pulling her out|
not come back|is not come back|look for him|look for her|search for him|search for her|had a fit|s had a fit|not with it|
pulled out of the water|pulled from the water|pulled out of the river|pulled from the river|been pulled out|fell in the river|fell into the river|fallen in the river|fallen into the river|fell in the water|fell into the water|
squashed|arm squashed|leg squashed|crushed under|can't account for|cannot account for|can't account for them|falling down the stairs|blood on his head|blood on her head|cold and confused|very cold and|
being treated|being treated there|confused and wandering|wandering about|very confused|disorientated|disoriented|
isn't getting up|isnt getting up|not getting up|won't get up|having a hypo|had a hypo|funny turn|had a turn|dangling from|left dangling|
cut badly|cut really badly|cut quite badly|cut pretty badly|cut quite bad|cut pretty bad|lot of blood|lots of blood|loads of blood|who's fallen|
through the ice|lost a finger|lost two fingers|lost his fingers|lost her fingers|lost some fingers|severed|mangled|
broke his wrist|broke her wrist|broken his wrist|broken her wrist|feeling faint|felt faint|feel faint|went faint|gone faint|
come over faint|came over faint|hit in the face|hit in the head|hit in the eye|hit in the chest|struck in the face|
can't find my nan|can't find my gran|can't find my grandma|can't find my grandad|can't find my grandpa|lost my nan|lost my gran|lost my grandma|
person fall|a person fall|man fall|woman fall|worker fall|fall from height|fell from height|fallen from height|
blood on head|have blood on|has blood on|head cut|bad head cut|nasty head cut|a bad cut|nasty cut|
someone is under|someone's under|somebody is under|somebody's under|someone under them|somebody under them|
been trampled|got trampled|was trampled|trampled by|been trampled on|overcome by fumes|overcome by the fumes|overcome by vapour|overcome by the vapour|
overcome by gas|overcome by the gas|
""".replace("\n", ""))

# "collapsed" alone is structural (hazard); "collapsed inside" / "passed out" is a person.

# Fights and violence: a danger only where the KB's own words say violence is one (a racecourse's "there's a fight,
# one man with a head wound" is the hurt man; a festival's "violence" in its danger's description makes the fight one).
VIOLENCE_CUES = """a fight|fight's broken out|fight has broken out|fight broke out|fight's kicked off|fight has kicked off|
fights breaking out|fighting with|lads fighting|men fighting|people fighting|blokes fighting|fans fighting|a brawl|brawl|
brawling|punch-up|punch up|a punch-up|scuffle|scuffles|a scuffle|fisticuffs|bottles flying|bottles being thrown|
throwing bottles|pulled a knife|waving a knife|brandishing a knife""".replace("\n", "").split("|")
VIOLENCE_WORDS = {"violence", "violent", "fight", "fights", "fighting", "brawl", "brawls", "disorder", "assault",
                  "assaults", "aggression", "affray"}

# Words that negate a following cue within a short window (same clause).
NEGATORS = {
    "no", "not", "never", "nobody", "none", "without", "zero", "isnt", "arent", "wasnt", "werent",
    "dont", "doesnt", "didnt", "hasnt", "havent", "cant", "cannot", "nothing", "neither", "nor",
    "nt",
}
NEGATOR_PHRASES = ["no one", "no longer", "not any", "free of", "clear of", "no sign of", "no signs of",
                   "no more", "not anymore", "any more", "no trace of", "no evidence of", "ruled out", "well away from",
                   "away from the", "far from the", "out of the way of", "upwind of the", "safe from the",
                   "fleeing the", "fled the", "escaping the", "escaped the", "sheltering from the", "shelter from the",
                   "refuge from the", "all clear on the", "all-clear on the", "all clear for the"]

# Hesitations a cancelling phrase may hold ("the fire at the granary is, er, out").
HESITATIONS = {"uh", "um", "er", "erm", "ah", "eh"}
# a person addressed by name after a repair word ("no Dad, it's the plank"; "no mate, the other one")
VOCATIVES = {"dad", "mum", "mam", "mom", "mummy", "daddy", "mate", "love", "son", "pal", "sir", "maam", "boss",
             "darling", "dear", "guys", "control", "gran", "nan", "grandad", "grandma", "pet", "duck", "hen", "lad",
             "lads", "bro", "buddy", "chief", "sarge", "skip", "skipper"}
# Phrases after a hazard cue that cancel it ("the fire is out").
# A clause right after a cue that takes it back ("they were safe, now they're not")
NO_LONGER_SO = [("now", "theyre", "not"), ("now", "they", "re", "not"), ("now", "its", "not"), ("now", "it", "isnt"),
                ("now", "they", "arent"), ("but", "not", "now"), ("not", "now"), ("not", "any", "more"), ("not", "anymore")]
CANCEL_AFTER = ["fully out", "is fully out", "damping down", "damping down is finished", "aboard now", "is aboard", "now aboard", "on board now", "safely aboard", "not any more", "not anymore", "cleared off", "it's cleared off", "wind's changed", "wind has changed", "that's cleared", "thats cleared", "it's cleared", "dried out", "has dried out",
                "s dried out", "hasn't got that far", "hasnt got that far", "not got that far", "hasn't got this far", "hasnt got this far",
                "not got this far", "hasn't reached us", "hasnt reached us", "blowing the other way", "blowing away from", "going the other way", "never reached", "didn't reach", "didnt reach", "hasn't reached", "hasnt reached", "never got to",
                "been cleared", "been cleared away", "been towed", "been towed away", "turned up", "has turned up", "s turned up", "turned up safe", "is out", "s out", "are out", "was out", "confirmed out", "properly out", "is properly out", "s properly out", "completely out", "is completely out", "s completely out", "is now out", "s now out", "are now out", "put out", "out now", "been put out",
                "has cleared", "have cleared", "s cleared", "has lifted", "s lifted", "has been lifted", "have lifted", "has gone down", "s gone down",
                "has receded", "s receded", "have receded", "gone down now", "has gone back down", "s gone back down", "gone back down", "off the boards now", "old news", "pumped it out",
                "pumped it all out", "brought down", "been brought down", "been broke loose", "been broken loose",
                "been broken up", "been broke up", "been freed", "running clean again", "backfilled", "been backfilled", "fenced off and backfilled", "is fenced off and backfilled", "been flown out", "flown out", "been airlifted", "airlifted out", "been airlifted out", "gone off site", "gone off site in the ambulance", "back together", "been reunited", "reunited with", "back with mum", "back with his mum", "back with her mum", "back with their mum", "it's landed", "its landed", "landed", "load's landed", "load has landed", "landed safely", "on the deck now",
                "all been brought down", "got them down", "nobody left", "water's gone down", "water has gone down",
                "water's receded", "water has receded", "flood's gone down", "flooding's gone down",
                "extinguished", "under control", "contained", "is over", "has stopped", "stopped",
                "died down", "died away", "has died away", "cleared up", "gone", "is gone", "has gone", "fixed", "repaired",
                "has eased off", "s eased off", "eased off",
                "turned off", "shut off", "capped", "receded", "drained", "false alarm",
                "all rescued", "rescued", "evacuated", "got out", "out safely", "accounted for",
                "no longer", "taken to hospital", "been taken to hospital", "been extracted",
                "been brought out", "been pulled out", "gone off in the ambulance", "gone off in an ambulance", "handed to the ambulance crew", "handed over to the ambulance", "been handed over",
                "been handed to the ambulance crew", "been shored", "shored up", "been shored up", "shored", "holding now", "it's holding",
                "knocked down", "been knocked down", "lifted off", "been lifted off", "winched up", "been winched up", "taken off",
                "been taken off", "picked up", "been picked up", "is resolved", "resolved", "withdrawn", "been withdrawn", "cancelled", "canceled", "is cancelled",
                "been cancelled",
                "was a mix up", "a mix up", "isolated", "been isolated", "made safe", "been made safe",
                "boomed off", "been boomed", "dispersed", "been dispersed", "cleaned up", "been cleaned up",
                "pumped out", "been pumped out", "no sign of him", "no sign of her", "no sign of them",
                "no sign of anyone", "no sign of anybody", "no one there", "nobody there",
                "off now", "s off now", "is off", "s off", "shut it off", "turned it off", "switched off",
                "switched it off", "sealed", "been sealed", "plugged", "been plugged", "is sorted", "s sorted", "been sorted", "been dealt with", "dealt with", "sorted", "sorted it", "nothing there now",
                "all sorted", "sorted now", "neutralised", "neutralized", "been neutralised", "been neutralized",
                "vented out", "been vented out", "been vented", "been closed off", "all gone", "s all gone", "leak has been closed off",
                "leak's closed off", "stood down", "have stood down", "has stood down", "was there already", "were there already",
                "been there for years", "old damage", "no new damage"] + [
                f"{verb} {who} out" for verb in ("got", "gotten", "taken", "took", "pulled", "brought")
                for who in ("him", "her", "them", "everyone", "everybody", "all of them", "the casualty")] + [
                "nobody was in", "no one was in", "nobody was inside", "no one was inside", "walked off",
                "nobody in", "no one in", "found her", "found him", "found them", "found safe",
                "not there yet", "hasn't reached", "has not reached", "not reached", "knocked that down",
                "knocked it down", "put that out", "put it out", "got that out",
                "he's been found", "she's been found", "they've been found",
                "walked out", "she's out", "he's out", "they're out", "she's okay", "he's okay", "they're okay",
                "she's fine now", "he's fine now", "they're fine now", "up and walking", "back on his feet",
                "back on her feet",
                "carried away", "been carried away", "been moved", "moved away",
                "empty"]
# ... of which these, said a few words after a place named again, end its danger ("the warehouse, oh, they've
# put that out now")
CANCEL_SAID_AGAIN = {"old news", "pumped it out", "pumped it all out", "pumped out", "water's gone down", "water has gone down", "water's receded", "water has receded",
                     "flood's gone down", "flooding's gone down", "put that out", "put it out", "knocked that down", "knocked it down", "extinguished",
                     "been put out", "got that out"}
# ... of which these revoke only a missing person ("lost child at the aviary, mum's found her")
CANCEL_MISSING_ONLY = {"found her", "found him", "found them", "found safe", "he's been found", "she's been found",
                       "they've been found", "turned up", "has turned up", "s turned up", "turned up safe",
                       "back together", "been reunited", "reunited with", "back with mum", "back with his mum",
                       "back with her mum", "back with their mum"}
MISSING_CUES = {"missing", "lost", "lost child", "last seen", "unaccounted for", "missing person", "missing persons",
                "not accounted for", "can't find", "cannot find", "lost contact with"}
# Words after which a cancelling phrase says what will end a danger, not that it has ended.
UNTIL_WORDS = {"till", "until", "til", "unless", "once"}
# Reasons of denials that say what cannot be done, not that a danger is gone ("can't get past the smoke").
ABILITY_NEGATIONS = ("negated by 'can't'", "negated by 'cant'", "negated by 'cannot'", "negated by 'couldn't'",
                     "negated by 'couldnt'", "negated by 'ca'")
# ... of which these are clauses of their own, after the one they revoke ("the missing man, no sign of him")
CANCEL_CLAUSES = {"no sign of him", "no sign of her", "no sign of them", "no sign of anyone", "no sign of anybody",
                  "no one there", "nobody there"}
# ... of which these revoke only a person in need ("gas leak at the police post, they evacuated" stands)
CANCEL_PEOPLE_ONLY = {"aboard now", "is aboard", "now aboard", "on board now", "safely aboard", "brought down",
                      "been brought down", "all been brought down", "got them down", "nobody left",
                      "all rescued", "rescued", "evacuated", "got out", "out safely", "accounted for",
                      "taken to hospital", "been taken to hospital", "been extracted", "been brought out",
                      "lifted off", "been lifted off", "winched up", "been winched up", "taken off", "been taken off",
                      "picked up", "been picked up", "handed to the ambulance crew", "handed over to the ambulance",
                      "been handed over", "been handed to the ambulance crew", "nobody was in", "no one was in",
                      "walked off", "empty", "nobody in", "no one in", "been flown out", "flown out", "been airlifted",
                      "airlifted out", "been airlifted out", "gone off site", "gone off site in the ambulance",
                      "nobody was inside", "no one was inside", "found her", "found him", "found them",
                      "found safe", "walked out", "she's out", "he's out", "they're out", "she's okay", "he's okay",
                      "they're okay", "carried away", "been carried away", "been moved", "moved away",
                      "she's fine now", "he's fine now", "they're fine now", "up and walking", "back on his feet",
                      "back on her feet"} | {
                      f"{verb} {who} out" for verb in ("got", "gotten", "taken", "took", "pulled", "brought")
                      for who in ("him", "her", "them", "everyone", "everybody", "all of them", "the casualty")}

# Words that open a clause speaking again of the thing just named ("..., it's drained now").
BACK_REFERENCE_WORDS = {"it", "its", "s", "is", "has", "been", "thats", "that", "was", "they", "theyre", "are", "re",
                        "have", "ve", "now", "all", "finally", "fully", "update", "updating", "latest", "theyve", "weve",
                        "ive"}

# Phrases that contain cue words but claim nothing ("the smoke alarm went off", "fire crew on site").
NEUTRAL_PHRASES = ["a bonfire", "cooking fires", "cooking fire", "holding, uh, but", "holding, but", "holding but",
                   # (a radio check: "reading you loud and clear")
                   "loud and clear", "reading you clear", "read you clear",
                   # (who reports the all-clear: "All clear from the stamp mill after the tremor")
                   "all clear from",
                   # (a notice put up: "tide tables are pinned up in the vols' hut")
                   "pinned up in", "pinned up on", "pinned up at", "pinned up by",
                   # (a verb of a relation: "the wall that shelters the yard")
                   "that shelters the", "which shelters the", "that shields the", "which shields the",
                   "it shelters from", "it shelters from the", "it shields from the",
                   # (a warning of what could set it off: "nobody goes in with anything that sparks")
                   "anything that sparks", "anything that could spark", "anything that might spark",
                   # (a warning, nothing comes down: "nobody come down here")
                   "nobody come down here", "no one come down here", "don't come down here", "do not come down here",
                   "nobody come down there", "don't come down there",
                   # (how far a place reaches, no flood: "the houses whose back gardens go right up to the car park")
                   "go right up to the", "goes right up to the", "went right up to the", "run right up to the",
                   "runs right up to the", "stretch right up to the", "stretches right up to the", "reach right up to the",
                   "reaches right up to the",
                   "out cold to the touch", "out and cold to the touch", "looking out over", "looks out over", "look out over", "looked out over", "been cleared out", "cleared out", "drill smoke", "exercise smoke", "smoke grenade", "smoke grenades", "burning hedge trimmings", "burning garden waste", "burning rubbish", "controlled burn", "fire drill", "evacuation drill", "fire practice", "half in the water", "i'm shattered", "im shattered", "i am shattered", "we're shattered", "we are shattered",
                   "keeping the children inside", "keeping the kids inside", "keeping everyone inside",
                   "keeping them inside", "kept the children inside", "kept the kids inside", "went under in the crash", "went bust", "gone bust", "above the flood line", "above the waterline", "above the water line", "above the flood level",
                   "above the high water mark", "roof is still on", "roof's still on", "been found safe", "found safe and well", "found safe at", "turned up safe and well", "turned up safe and sound",
                   "turned up safe", "found safe and sound", "stable staff", "stable lads", "stable lad", "stable hands", "stable hand", "stable girls",
                   "stable block", "stable door", "stable doors", "use it to bring", "use it to get", "use it to take", "use it to move", "use it to evacuate",
                   "use that to bring", "use that to get", "out of use", "out of action", "out of service", "out of the smoke", "away from the smoke", "out of the rain", "out of the water", "out of the fumes",
                   "people sitting in here", "people sitting in there", "sitting in here", "waiting in here",
                   "i'm calling from", "im calling from", "i am calling from", "we're calling from",
                   "i'm ringing from", "im ringing from", "we're ringing from", "where i'm calling from", "can't get down to", "cannot get down to", "comes down to", "come down to", "coming down to", "goes down to", "runs down to", "keep clear", "stay clear", "keep everyone clear", "keep everybody clear", "keep people clear",
                   "keeping clear", "staying clear", "keeping everyone clear", "keeping everybody clear",
                   "keeping people clear", "keeping them clear", "keeping the public clear", "keeping well clear",
                   "keep them clear", "keep the public clear", "keep well clear", "clear the public", "keep it clear",
                   "keep that clear", "keep this clear",
                   "you're breaking up", "youre breaking up", "you are breaking up", "breaking up on me", "you keep breaking up",
                   "signal's breaking up", "signal is breaking up", "radio's breaking up", "line's breaking up",
                   "clear everyone away", "clear everybody away", "clear people away", "clear the crowd",
                   "gas monitor", "gas monitors", "gas detector", "gas detectors", "gas reading", "gas readings",
                   "flood tide", "ebb tide", "on the ebb", "burnt toast", "burned toast", "burnt food", "burned food",
                   "smoke alarm", "smoke alarms", "smoke machine", "smoke machines", "fog machine", "haze machine", "fire alarm", "fire alarms", "fire exit", "fire escape",
                   "fire brigade", "fire crew", "fire engine", "fire truck", "fire service", "fire department",
                   "fire control", "fire and rescue", "fire officer", "fire chief", "fire ground commander",
                   "no naked flames", "no naked flame", "no naked lights", "no open flames", "no smoking",
                   "keeping the smoke off", "keeping the smoke away", "keeps the smoke off", "keeps the smoke away",
                   "blowing the smoke away", "keeping the water out", "keeps the water out",
                   "fire team", "firefighter", "firefighters", "fire fighter", "fire fighters", "fire hydrant",
                   "cleared off", "it's cleared off", "fire proofed", "fire-proofed", "fireproofed", "fireproof", "fire proof", "fire resistant",
                   "fire's lit", "fire is lit", "fires lit", "lit the fire", "wood burner",
                   "quiet now", "is quiet", "all quiet", "walked home", "gone home", "went home", "got himself out",
                   "got herself out", "got themselves out",
                   "flood warden", "flood wardens", "fire warden", "fire wardens", "fire marshal", "fire marshals",
                   "fire officer", "fire officers", "flood team", "flood officer", "flood defence team",
                   "fire door", "gas mask", "gas masks", "gas company", "gas board", "gas man", "gas men",
                   "gas engineer", "gas engineers", "gas crew", "gas team", "gas network", "gas fitter",
                   "hazmat crew", "hazmat team", "hazmat unit", "hazmat officer", "hazmat crews", "hazmat teams",
                   "by hazmat", "not shifting", "isn't shifting", "won't shift", "safe word", "safety officer", "clear the area",
                   "all units", "flood light", "floodlight", "floodlights", "rescue team", "rescue teams",
                   "took everyone out", "got everyone out", "brought everyone out", "had everyone out",
                   "nobody home", "no one home", "nobody at home", "no one at home",
                   "waiting for the all clear", "wait for the all clear", "awaiting the all clear",
                   "until the all clear", "until we get the all clear", "waiting on the all clear"]

# A jam freed, water running as it should ("the log jam's been broke loose and water's running clean again")
NEUTRAL_PHRASES += ["been broke loose", "been broken loose", "running clean again", "water's running clean",
                    "water is running clean", "running clear again", "water's running clear"]
# The snake that bit someone: what hurt the person, no danger said of the place ("bitten by a snake")
NEUTRAL_PHRASES += ["by a snake", "by the snake", "by a viper", "by an adder", "by the adder"]
# What a controller clears a craft or crew to do ("you're cleared to taxi from the south dock"): leave to move, no
# place said safe
NEUTRAL_PHRASES += [f"cleared {p} {move}" for p in ("to", "for") for move in (
    "taxi", "land", "landing", "take off", "takeoff", "depart", "departure", "launch", "proceed", "enter", "cross",
    "push back", "pushback", "start up", "climb", "descend", "approach", "lift off", "sail", "berth", "fly", "flight")]

# A report framed as an exercise or a training message: nothing in it is real, in any sentence ("Exercise, exercise,
# exercise. Simulated casualty on the footbridge. Exercise ends."). "exercise exercise" counts only as the opening.
EXERCISE_OPENING = ("exercise", "exercise")
EXERCISE_FRAME = ["this is an exercise", "this is a drill", "training scenario", "training message", "exercise scenario",
                  "exercise only", "simulated casualty", "simulated casualties", "no actual persons", "no real persons",
                  "nothing is actually happening", "nothing's actually happening", "exercise ends", "end of exercise",
                  "endex", "exercise planned for", "exercise is cancelled", "exercise has been cancelled",
                  "exercise planned", "drill planned for", "drill is cancelled"]

# A warning or report taken back by name ("please withdraw my earlier warning"): a false alarm that withdraws
# the whole report before it.
_WITHDRAWN_WARNINGS = ["withdraw my earlier warning", "withdraw my warning", "withdraw my earlier report", "withdraw my last",
                       "withdraw that warning", "withdraw the warning", "withdraw my report"]

# False alarms that only say what a danger was ("it's just steam"): a person hurt in the same sentence stays hurt.
DANGER_EXPLAINED = {"just steam", "only steam", "just fog", "only fog", "just mist", "only mist", "someone's extractor fan",
                    "someones extractor fan", "their extractor fan", "just the extractor fan", "only the extractor fan",
                    "was the extractor fan", "controlled burn", "controlled bonfire", "controlled fire", "burning the prunings",
                    "burning prunings", "burning off the", "burning leaves in a brazier", "burning leaves in a",
                    "was a barbecue", "just exhaust", "only exhaust", "just the exhaust", "only the exhaust", "was a bbq", "was a bonfire", "it's a bonfire", "its a bonfire", "it's just a bonfire",
                    "it's only a bonfire", "it's a barbecue", "its a barbecue", "garden bonfire"}

# Whole-report "nothing to see" markers that cancel every claim in their sentence.
FALSE_ALARM = ["false alarm", "smoke from the cooking fires", "smoke from the cooking fire", "smoke from a cooking fire", "scratch their earlier call", "scratch my earlier call", "scratch our earlier call",
               "nobody's gone in", "no one's gone in", "nobody went in", "nothing's happened at ours",
               "nothing has happened at ours", "that was yesterday's call", "that was yesterday", "exercise exercise", "for the exercise only", "that's for the exercise",
               "none of this is real", "this is a test message", "the scenario has", "tomorrow's exercise",
               "in the exercise", "stand down on the", "standing down on the", "stood down on the", "never mind", "nevermind", "disregard my last", "disregard the last report", "scratch that report", "scratch my last",
               "nothing in it", "nothing to it", "on purpose", "controlled burn", "controlled bonfire", "controlled fire", "burning the prunings", "burning prunings", "burning off the", "like they do every", "just steam", "only steam", "just fog", "only fog", "just mist", "only mist", "just exhaust", "only exhaust", "just the exhaust", "only the exhaust", "someone's extractor fan", "someones extractor fan", "their extractor fan", "just the extractor fan", "only the extractor fan", "was the extractor fan", "was just a", "was only a",
               "was just their", "was just the", "its just their", "is just their", "its only their", "nothing to worry about", "ignore my last", "cancel my last",
               "disregard my last message", "nobody in any", "disregard the call about", "disregard the call re", "disregard the report about", "disregard the call from", "burning leaves in a brazier", "burning leaves in a", "disregard previous", "disregard my earlier report",
               "ignore my earlier report", "disregard the earlier report", "disregard the earlier message",
               "disregard the last message", "disregard my earlier message", "disregard the previous message",
               "faulty detector", "faulty sensor", "faulty alarm", "false reading", "detector fault", "were wrong", "were unfounded",
               "was unfounded", "were false", "are false", "are wrong", "are unfounded", "was false",
               "is false", "are untrue", "were untrue", "turned out to be false", "turned out to be wrong",
               "part of a drill", "part of the drill", "just a drill", "only a drill", "part of the exercise",
               "part of an exercise", "just an exercise", "only an exercise", "is stood down", "been stood down",
               "was stood down", "are stood down", "was a mannequin", "was a dummy", "was a training dummy",
               "was a barbecue", "was a lost bag", "was a lost rucksack", "was a lost backpack", "was a lost suitcase", "owner's come back for it", "owner has come back for it", "owner came back for it", "was a bbq", "was a bonfire", "was someone's barbecue", "job closed", "incident closed",
               "it's a bonfire",
               "its a bonfire", "it's just a bonfire", "it's only a bonfire", "it's a barbecue", "its a barbecue",
               "disregard all of it", "disregard all of that", "disregard all that", "ignore all of that", "ignore all of it",
               "ignore me", "nothing showing", "no fire showing", "nothing found", "found nothing", "nothing ongoing", "it is nothing", "it's nothing", "its nothing", "there's nothing",
               "theres nothing", "there is nothing", "i've got nothing", "got nothing here", "all normal",
               "all looks normal", "everything normal", "everything's normal", "it's a long way off",
               "its a long way off", "it's miles away", "its miles away", "it's a long way away", "its a long way away",
               "was only the", "was only them", "was just them", "were only", "was only someone", "was only some",
               "ignore it", "all sorted", "nothing's happened yet", "nothing has happened yet", "nothing happened yet",
               "nothing's fallen yet", "nothing has fallen yet", "nothing's come down yet", "nothing has come down yet", "it's all sorted", "garden bonfire", "was somebody's", "is rubbish", "is nonsense",
               "nothing happening at", "there's nothing there", "nothing there at all", "that was ages ago", "was just asleep",
               "nothing doing there", "disregard the man", "disregard the woman", "disregard the casualty", "that was wrong it was a", "that was wrong it was just",
               "been checked it was the", "been checked it was just", "been checked it was only", "checked it was the",
               "checked it was just", "checked it was only",
               *_WITHDRAWN_WARNINGS]
# ... unless the words after them go on to say what there is none of ("there's nothing left of it", "it's nothing
# serious", "there's nothing we can do")
FALSE_ALARM_NOT_BEFORE = {"left", "serious", "major", "like", "but", "we", "i", "you", "they", "else", "more", "to",
                          "much", "stopping", "holding", "between", "in", "on", "at"}
# ... of which these say what the thing said before them was: what follows them is not denied
DISMISSED_BEFORE = {"been checked it was the", "been checked it was just", "been checked it was only", "checked it was the",
                    "checked it was just", "checked it was only", "it's a bonfire", "its a bonfire", "it's just a bonfire", "it's only a bonfire", "it's a barbecue",
                    "its a barbecue", "is stood down", "been stood down", "was stood down", "are stood down", "was a mannequin",
                    "was a dummy", "was a training dummy", "was a barbecue", "was a bbq", "was a bonfire",
                    "was someone's barbecue"}
# ... of which these withdraw everything said before them, in earlier sentences as well
WHOLE_REPORT_WITHDRAWN = {"disregard all of it", "disregard all of that", "disregard all that", "ignore all of that",
                          "ignore all of it", "ignore me", *_WITHDRAWN_WARNINGS}
# ... and these, with those, an earlier report: only what comes before them in the sentence is denied
PREVIOUS_REPORT_WITHDRAWN = {"disregard my last", "disregard the last report", "scratch that report", "scratch my last", "ignore my last", "cancel my last",
                             "disregard my last message", "disregard previous", "never mind", "nevermind",
                             *WHOLE_REPORT_WITHDRAWN}

# Self-repair markers. Strong ones reach back into the previous sentence.
STRONG_REPAIR = [
    "no wait", "wait no", "no no", "correction", "scratch that", "strike that", "disregard that",
    "i mean", "i meant", "i misspoke", "my mistake", "my bad", "let me correct", "let me rephrase",
    "negative", "check that", "cancel that", "wrong", "that's wrong", "thats wrong", "not right",
    "make that", "sorry i mean", "sorry i meant", "belay that", "correcting", "i said wrong",
    "wrong one", "not that one", "wrong building", "wrong place", "as you were", "amend that", "hold that", "hold on that", "let me correct that", "let me correct myself",
    "let me correct my last", "that should be", "that should have been", "should be", "scrub that", "i misspoke",
    "ah i misspoke", "or is it", "take that back", "strike that last", "correction on my last", "correct that",
    "scrap that", "bin that", "ignore that", "delete that", "disregard", "corrects to", "corrected to",
    "correcting to", "changed to", "then changed to", "changes it to", "changed it to", "what am i saying",
    "what am i on about", "i'm getting mixed up", "im getting mixed up", "getting mixed up", "i've got that wrong",
    "ive got that wrong", "got that wrong", "hold up", "edit", "corrects her", "corrects him", "corrected her",
    "corrected him", "corrects me", "corrected me", "rewind", "back up", "start again", "let me start again",
    "change of plan", "change of plans", "plans have changed", "withdrawing that", "i'm withdrawing that",
    "i withdraw that", "i take that back", "tell a lie", "wrong block", "caller corrects", "caller corrected",
    "caller correcting", "caller now says", "he corrects", "she corrects", "they correct", "crew corrects",
    "she's right", "he's right", "you're right", "they're right", "second voice", "voice behind",
    "voice in background", "voice in the background", "background voice", "another voice",
    "i'm all turned round", "i'm all turned around", "all turned round", "all turned around", "i got confused",
    "i'm confused", "got my bearings wrong", "i beg your pardon", "beg your pardon", "pardon me",
    "sorry meant", "meant to say", "i meant to say",
]
WEAK_REPAIR = ["sorry", "actually", "or rather", "rather", "wait", "no", "nope", "nah", "naw", "er no", "uh no", "well no",
               "oops", "whoops", "hang on", "hold on"]

# Spatial phrases that link a described place to a landmark; relation names in the KB are
# matched verbatim ("attached_to" -> "attached to") and through these synonyms.
RELATION_SYNONYMS: dict[str, list[str]] = {
    "attached to": ["attached to", "built onto", "built on to", "joined to", "joined onto", "joined on to",
                    "connected to", "adjoining", "adjoins", "adjoin", "attached onto", "stuck onto", "stuck to",
                    "sharing a wall with", "shares a wall with", "that shares a wall with", "built against",
                    "abutting", "abuts", "butting onto", "bolted onto", "tacked onto", "stuck on to",
                    "built up against", "fixed onto", "part of the same building as", "joined up with",
                    "sharing a party wall with", "shares a party wall with", "that shares a party wall with",
                    "party wall with", "built hard against", "built against", "backing on to", "built on the side of",
                    "built onto the side of", "built on to the side of", "stuck on the side of", "built on the end of",
                    "built onto the end of", "built on to the end of", "stuck on the end of", "tacked on the end of"],
    "next to": ["next to", "next door to", "next door", "beside", "next building over from", "next one over from",
                "next along from", "next one along from", "the next building over from", "next door along from", "besides", "alongside", "adjacent to", "right by",
                "right next to", "just next to", "by", "neighbouring", "neighboring", "next door from",
                "immediately next to", "directly next to", "to the side of", "next 2"],
    "across from": ["across from", "opposite", "opposite to", "across the street from", "across the road from",
                    "facing", "over the road from", "across the square from", "across the way from",
                    "over the street from", "directly across from", "straight across from", "that faces",
                    "faces", "opposite of", "over the way from", "across the way", "on the other side of the road from",
                    "on the opposite side of the street from", "that looks across at", "looks across at",
                    "looks across to", "looking across at", "looking across to", "looks across the road at",
                    "looks across the square at", "looks across the street at", "across the road", "across the street",
                    "over the road", "over the way", "across the lane from", "over the lane from", "across the lane",
                    "over the lane", "across the alley from", "across the track from", "over the track from",
                    "across the green from", "across the yard from", "over the yard from", "across the car park from",
                    "across the street of", "across the road of", "in opposite of",
                    "on the opposite of", "on the other side of the street of", "on the other side of the road of"],
    "behind": ["behind", "round the back of", "around the back of", "at the back of", "in back of",
               "back of", "to the rear of", "at the rear of", "out back of", "directly behind", "right behind",
               "just behind", "backs onto", "backing onto", "that backs onto", "round behind", "out the back of",
               "back behind", "built against the back of", "built onto the back of", "built on to the back of",
               "against the back of", "up against the back of", "stuck on the back of", "tacked onto the back of", "behind of", "in behind of"],
    "set into": ["set into", "built into", "sunk into", "let into", "set right into", "built right into", "set in to",
                 "built in to"],
    "in front of": ["in front of", "out front of", "directly in front of", "right in front of", "at the front of"],
    "inside": ["inside", "within"],
    "above": ["above", "on top of", "upstairs from", "overlooks", "overlooking", "overlook", "looks over",
              "looking over", "looks down on", "looking down on", "looking down over", "looks down over", "look down over",
              "looks down onto", "looking down onto", "looks down at", "up above", "up from",
              "higher than", "uphill from", "up the hill from", "looms over", "looming over", "looks out over",
              "looking out over", "towers over", "towering over", "stands over", "sits above", "stands above",
              "directly over", "right over", "immediately over", "sits over", "sitting over", "lies over",
              "sits on top of", "sitting on top of", "sits right over", "sits directly over"],
    "below": ["below", "under", "underneath", "beneath", "downstairs from", "down below", "overlooked by",
              "looked over by", "down from", "downhill from", "down the hill from", "at the foot of"],
    "upstream of": ["upstream of", "upstream from", "up the river from", "upriver of", "upriver from",
                    "up the stream from", "further up the river from"],
    "downstream of": ["downstream of", "downstream from", "down the river from", "downriver of", "downriver from",
                      "down the stream from", "further down the river from"],
    "north of": ["north of", "to the north of", "northside of"],
    "south of": ["south of", "to the south of"],
    "east of": ["east of", "to the east of"],
    "west of": ["west of", "to the west of"],
    "near": ["near", "close to", "near to", "nearby"],
}
# Word swaps that turn a relation phrase into its inverse ("upstream of" <-> "downstream of").
ANTONYMS = {"upstream": "downstream", "downstream": "upstream", "upriver": "downriver", "downriver": "upriver",
            "above": "below", "below": "above", "over": "under", "under": "over", "north": "south",
            "south": "north", "east": "west", "west": "east", "uphill": "downhill", "downhill": "uphill",
            "before": "after", "after": "before", "upstairs": "downstairs", "downstairs": "upstairs",
            "front": "back", "back": "front", "inside": "outside", "outside": "inside", "higher": "lower",
            "lower": "higher", "feeds": "fed", "supplies": "supplied", "seaward": "landward",
            "landward": "seaward", "inland": "seaward", "up": "down", "down": "up", "upwind": "downwind",
            "downwind": "upwind", "windward": "leeward", "leeward": "windward", "forward": "aft", "aft": "forward",
            "fore": "aft", "ahead": "astern", "astern": "ahead", "port": "starboard", "starboard": "port"}
# Direction words of relation names, each with the ways a report says it; a relation named with
# one ("seaward_of", "uphill_from") is also matched by the others, and backwards by the opposite family.
DIRECTION_FAMILIES: dict[str, list[str]] = {
    "seaward": ["seaward", "seawards", "on the seaward side", "on the sea side", "out to sea", "nearer the sea",
                "further out", "on the water side"],
    "landward": ["landward", "landwards", "inland", "on the landward side", "on the land side", "shoreward",
                 "on the inland side", "further inland", "on the shore side"],
    "uphill": ["uphill", "up the hill", "above", "higher up", "further up the hill", "up the slope", "upslope"],
    "downhill": ["downhill", "down the hill", "below", "beneath", "lower down", "further down the hill",
                 "down the slope", "downslope"],
    "upstream": ["upstream", "upriver", "up the river", "further up the river", "up the stream"],
    "downstream": ["downstream", "downriver", "down the river", "further down the river", "down the stream"],
}
OPPOSITE_DIRECTION = {"seaward": "landward", "landward": "seaward", "uphill": "downhill", "downhill": "uphill",
                      "upstream": "downstream", "downstream": "upstream"}
# Direction words that stand alone, without "of" / "from" ("the houses above the net loft").
BARE_DIRECTIONS = {"above", "below", "beneath"}

# First words of relation names that are not verbs ("next_to", "across_from", "part_of").
NOT_VERBS = {"next", "across", "opposite", "adjacent", "near", "behind", "under", "over", "above", "below", "beside",
             "inside", "outside", "part", "close", "directly", "just", "right", "round", "around", "along",
             "alongside", "within", "between", "beyond", "against", "off", "onto", "into", "up", "down", "by", "to",
             "from", "of", "the", "a", "an", "in", "on", "at", "upstream", "downstream", "uphill", "downhill", "north",
             "south", "east", "west", "beneath", "underneath", "atop", "top", "front", "back", "facing", "same",
             "nearest", "closest", "connected", "attached", "joined", "adjoining", "upriver", "downriver",
             "left", "far", "other", "twin", "sister", "home", "main", "entrance", "exit", "via", "through", "past"}
# Irregular past participles of verbs that name relations ("fed_by" is said "the mill that feeds ...").
IRREGULAR_PARTICIPLES = {"fed": "feed", "built": "build", "held": "hold", "led": "lead", "lit": "light", "ran": "run",
                         "dug": "dig", "hung": "hang", "laid": "lay", "kept": "keep", "fitted": "fit", "shaded": "shade",
                         "overshadowed": "overshadow", "drawn": "draw", "sunk": "sink", "bound": "bind"}
# Word stems that name the same link between two places ("supplied by" / "fed by" / "powered by").
LINK_SYNONYMS = [{"suppl", "feed", "power", "serv"}, {"pair", "twin", "sister", "partner"}, {"link", "connect", "join"},
                 {"annex", "extension"},
                 {"tunnel", "underpas", "subway", "passag"}, {"bridg", "walkway", "footbridg"},
                 {"moor", "tied", "tie", "berth"}, {"foot", "bottom"}, {"vent", "exhaust"},
                 {"monitor", "watch", "observ", "surveil"}, {"supersed", "replac"}, {"empt", "discharg"}]
# Words of a relation name that are too common to identify it on their own in a report.
RELATION_NAME_STOPWORDS = {"busy", "for", "by", "to", "of", "with", "onto", "on", "into", "from", "the", "a", "an", "is", "and", "in",
                           "at", "that", "its", "it", "side", "end", "other", "way", "same", "far", "near", "up",
                           "down", "over", "across", "back", "out", "off", "through", "under", "above", "below",
                           "next", "behind", "front", "beside", "along", "round", "around", "opposite", "facing",
                           "directly", "just", "right", "left", "part", "one", "building", "place", "site",
                           "has", "have", "had", "are", "was", "were", "be", "been", "get", "gets", "got", "does"}

SYMMETRIC_HINTS = ("next", "adjacent", "beside", "across", "opposite", "adjoin", "near", "attached", "connected",
                   "joined", "facing", "faces", "neighbo", "abut", "border", "touch", "share", "bord", "cheek by jowl",
                   "side by side", "back to back", "shoulder to shoulder", "hard by")

# "X in front of Y" is "Y behind X": a report phrase read against the opposite KB relation.
INVERSE_PHRASES = {"in front of": "behind", "behind": "in front of", "above": "below", "below": "above",
                   "north of": "south of", "south of": "north of", "east of": "west of", "west of": "east of",
                   "upstream of": "downstream of", "downstream of": "upstream of",
                   "underneath": "above", "beneath": "above"}
# Words between an anchor and a trailing relation: "the one the garage sits behind".
INVERSE_VERBS = {"sits", "sit", "is", "s", "stands", "stand", "lies", "lie", "located", "situated", "are", "was",
                 "right", "directly", "just"}
# Parts of any premises: after a report opens on where the speaker is, "the yard" is that place's yard.
PREMISES_PARTS = {"yard", "courtyard", "forecourt", "garden", "gardens", "grounds", "lawn", "playground", "kitchen",
                  "cellar", "carpark"}
# Words of harm done whose kind is that of what did it ("damaged by the blast", "cracked in the quake")
HARM_WORDS = {"damaged", "damage", "cracked", "wrecked", "hit", "destroyed", "flattened", "gutted", "smashed",
              "shattered", "broken", "weakened", "struck", "affected", "battered", "holed", "buckled", "twisted", "warped"}
# Vehicles: things, not places, that a relation word may follow ("a car swept against the arch")
VEHICLE_WORDS = {"car", "cars", "van", "vans", "lorry", "lorries", "bus", "truck", "trucks", "vehicle", "vehicles",
                 "tractor", "boat", "boats", "coach", "taxi", "ambulance", "bike", "motorbike"}
# Bodies of water a flood brings in ("it's got the river in the bar")
WATER_BODIES = {"river", "sea", "tide", "brook", "beck", "burn", "stream", "canal", "lake", "loch", "mere", "creek"}
# Water itself, a substance: said bare it is the water, not a landmark whose name opens with the word
WATER_WORDS = frozenset({"water", "waters", "floodwater", "flood"})
# Verbs of taking people somewhere ("we've moved our old people up to the chapel")
MOVING_VERBS = {"moved", "moving", "taken", "taking", "took", "brought", "bringing", "sent", "sending", "walked",
                "ferried", "evacuated", "shifted", "got"}
# Which one of a row or group ("the end one", "the first one")
# ways to a place: "guards the road to" said "the road up to it"
WAY_NOUNS = {"road", "track", "path", "lane", "drive", "way", "approach", "steps", "stairs", "ramp", "walk", "access"}
MEMBER_WORDS = {"end", "first", "last", "second", "third", "middle", "corner", "nearest", "far", "top", "bottom"}
# Words for a room or part of a place said right after its name ("the Chlorine Palace sports hall")
# Rooms and floors of a building: "the room above the market hall" is in it
ROOMS_OF_A_BUILDING = _keyed({"room", "rooms", "flat", "flats", "loft", "attic", "cellar", "basement", "floor", "floors"})
ROOM_WORDS = _keyed({"sports", "function", "main", "waiting", "staff", "hall", "room", "rooms", "kitchen", "bar",
                     "lounge", "basement", "canteen", "foyer", "annexe", "yard", "car", "park"})
# Rooms of any premises, said after where a crew is ("we're at the halt and the waiting room's ...")
PREMISES_ROOMS = {("waiting", "room"), ("staff", "room"), ("function", "room"), ("back", "room"), ("main", "hall"),
                  ("ground", "floor"), ("top", "floor"), ("first", "floor")}
# Words that open a clause with a subject of its own ("..., we've got smoke").
CLAUSE_SUBJECTS = {"i", "im", "ive", "we", "were", "weve", "he", "hes", "she", "shes", "they", "theyre", "theyve",
                   "it", "its", "there", "theres", "you", "youre", "everyone", "someone", "nobody"}
# "stuck ... for ages", "stuck in traffic": held up on the way, not trapped.
HELD_UP = {("in", "traffic"), ("in", "the", "traffic"), ("in", "a", "queue"), ("in", "the", "queue"), ("in", "a", "jam"),
           ("in", "a", "tailback"), ("in", "the", "tailback")}
# Things said to be "in the water" that are no person: debris of a flood ("logs everywhere in the water").
FLOATING_THINGS = {"log", "logs", "timber", "debris", "car", "cars", "caravan", "caravans", "barrel", "barrels", "bin",
                   "bins", "tree", "trees", "branch", "branche", "pallet", "pallets", "rubbish", "plank", "planks",
                   "drum", "drums"}
# Things that may end up in the water with no person in it ("the crane's in the water")
SUNK_THINGS = FLOATING_THINGS | {"crane", "cranes", "container", "containers", "trailer", "trailers", "boom"}
# Other words for the same kind of place: a KB whose one chapel is "the chapel" is meant by "the church" too,
# where no landmark is called a church (see ``analyzer._synonym_forms``).
PLACE_SYNONYMS = [{"church", "chapel", "kirk"}, {"cafe", "café", "tearoom", "caff"},
                  {"pharmacy", "chemist", "drugstore"}, {"school", "academy"}]
# Who a call sign calls ("Station two to control"): a place said just before "to" one of these is the caller's.
CALL_RECEIVERS = {("control",), ("base",), ("dispatch",), ("command",), ("all",), ("ops",), ("hq",), ("comms",)}
# Relation words too common to resolve without a head noun ("blocked by the bank").
AMBIGUOUS_HEADLESS = {("by",), ("inside",), ("within",), ("near",), ("above",), ("below",), ("before",), ("under",),
                      ("over",), ("underneath",), ("beneath",), ("on", "top", "of")}

# Nouns that describe a place generically; "the shop attached to X" is a relational reference.
GENERIC_HEADS = {
    "shop", "store", "building", "place", "house", "one", "unit", "premises", "structure", "site",
    "block", "office", "hall", "station", "centre", "center", "business", "spot", "property", "venue",
    "facility", "storefront", "shopfront", "outlet", "annex", "annexe", "extension", "warehouse",
    "garage", "shed", "barn", "hut", "home", "residence", "tower", "depot", "yard", "lot", "area",
    "establishment", "complex", "crossing", "footbridge", "landing", "jetty", "wharf", "quay", "cottage", "cottages", "church", "school", "clinic", "restaurant", "pub", "bar", "market",
    "bridge", "mill", "plant", "factory", "workshop", "cabin", "dock", "pier", "square",
    "park", "field", "ground", "grounds", "point", "thing", "bit", "side", "corner", "room",
    "space", "green", "lawn", "garden", "gardens", "road", "street", "lane", "alley", "terrace", "plot", "land", "apartments",
    "flats", "bay", "wing", "hotel", "inn", "library", "hospital", "quarter", "section", "zone", "ones",
    "neighbour", "neighbor", "door", "location", "address", "greenspace", "premise", "whatever", "wherever", "whichever", "whoever", "everything", "what", "works", "work",
    "row", "parade", "arcade", "kiosk", "stall", "lodge", "chapel", "compartment", "tent", "deck", "campsite",
}

FILLERS = HESITATIONS | {"hmm", "like", "so", "okay", "ok", "well", "yeah", "right",
           "just", "basically", "kinda", "sorta", "literally", "over", "copy", "roger", "base", "team",
           "whatsit", "wotsit", "thingy", "thingummy", "whatchamacallit", "whatsitsname"}
# Words a speaker may drop inside a cue phrase without changing it ("roof's partly down", "on, uh, fire").
CUE_SKIPPABLE = HESITATIONS | {"hmm", "like", "partly", "partially", "completely", "totally",
                 "fully", "badly", "really", "very", "now", "still", "already", "entirely", "half", "kinda", "sorta",
                 "properly", "seriously", "pretty", "right", "just"}
# Words that open a sentence as a description, not as a name without its article ("Light smoke at ...").
DESCRIPTIVE_WORDS = {"light", "heavy", "thick", "black", "white", "grey", "gray", "dense", "small", "big", "large",
                     "minor", "major", "main", "little", "old", "new", "green", "red", "amber", "tower"}
ARTICLES = {"the", "a", "an", "that", "this", "those", "these"}
DETERMINERS = {"the", "a", "an", "that", "this", "those", "these", "its", "their", "our", "some", "old", "little"}
PREPOSITIONS = {"at", "in", "on", "inside", "near", "from", "by", "outside", "behind", "around", "into",
                "within", "of", "to", "towards", "toward", "under", "over", "across", "through", "beside",
                "next", "out", "along", "past", "up", "down", "for", "with"}
# "the first one", "the latter": which member of the last list of places said
ORDINAL_PLACES = {"first": 0, "second": 1, "third": 2, "fourth": 3, "former": 0, "latter": -1}
# verbs that may follow a bare ordinal anaphor ("the first reports a spill", "the latter looks worse")
ANAPHOR_VERBS = {"reports", "reported", "says", "said", "looks", "look", "needs", "seems", "sounds", "still", "though",
                 "also", "too", "definitely", "really", "just", "now", "then", "as", "being"}
# words that make a sentence a correction of an earlier one ("T2 corrects previous msg: NOT lower field")
CORRECTION_WORDS = {"correct", "corrects", "corrected", "amend", "correction", "correcting", "amended", "amends", "mistake", "wrong",
                    "scratch", "scrap", "disregard"}
# words that only say where a place is ("the roof of the bakery", "the kiosk at the services"), not a relation
LOCATIVE_LINKS = {"of", "at", "in", "on", "inside", "near", "by", "outside", "within", "the", "a", "an", "its"}
# words that open the rest of a description after its head ("the place you row out to", "the bay with a door")
DESCRIPTION_OPENERS = {"that", "which", "where", "whose", "you", "they", "we", "i", "he", "she", "with", "just", "right",
                       "directly", "straight", "whatever", "before", "after", "behind", "beyond", "past", "above",
                       "below", "beneath", "under", "underneath", "opposite", "across", "beside", "towards", "toward",
                       "up", "down", "over", "round", "around"}
# what opens a sighting right after a place passed ("going past the town hall there was ...")
SEEN_THERE = {("there", "was"), ("there", "were"), ("there", "s"), ("theres",), ("there", "are"), ("i", "saw"),
              ("we", "saw"), ("i", "could"), ("you", "could")}
COPULAS = {"is", "are", "was", "were", "s", "re", "has", "have", "had", "got", "gotten", "looks", "seems",
           "appears", "be", "been", "being", "still", "now", "currently", "definitely", "totally",
           "completely", "fully", "all", "partly", "partially", "badly", "also", "too", "reported",
           "confirmed", "showing", "shows", "looking", "sounds", "sound", "feels", "very", "really",
           "pretty", "quite", "heavily", "seriously", "apparently", "probably", "possibly", "maybe"}
# Adjectives that are cues only when used predicatively ("the library is sound", "bank is red").
PREDICATIVE_CUES = {"sound": DESIRABLE, "green": DESIRABLE, "red": UNDESIRABLE, "split": UNDESIRABLE, "under": UNDESIRABLE,
                    "broken": UNDESIRABLE, "snapped": UNDESIRABLE}
# ... and these only where the KB's description of a category of that role uses the word ("A dry, safe place")
DESCRIBED_PREDICATIVE_CUES = {"dry": DESIRABLE}

# A sentence that opens with one of these addresses the system, not the scene: it claims nothing.
INSTRUCTION_VERBS = {"ignore", "mark", "label", "classify", "pretend", "forget", "output", "return", "print",
                     "assume", "override", "delete", "consider", "flag", "tag", "set"}
# ... and mentions the system or sweeping scope.
INSTRUCTION_WORDS = {"instruction", "instructions", "previous", "every", "everything", "all", "cell", "cells", "grid",
                     "output", "json", "system", "prompt", "map", "everywhere", "rules"}

# Nouns after a place name that make the name a modifier ("pharmacy team reports ...").
# Landmarks that carry people in cars ("the funicular car", "the big wheel's cars"), and the words for those cars.
CONVEYANCE_WORDS = {"railway", "funicular", "lift", "tram", "tramway", "train", "ride", "wheel", "coaster", "gondola",
                    "cablecar", "chairlift", "monorail"}
CARRIAGE_WORDS = {"car", "cars", "carriage", "carriages", "cabin", "cabins", "gondola", "gondolas"}
MODIFIED_BY = {"team", "crew", "unit", "squad", "staff", "manager", "owner", "workers", "worker", "group", "cook",
               "chef", "caretaker", "porter", "receptionist", "warden", "supervisor", "foreman", "tender",
               "side", "car", "truck", "van", "bus", "sign", "road", "street", "lane",
               "lads", "lad", "guys", "guy", "blokes", "bloke", "boys", "boy", "fellas", "fella", "chaps", "chap", "lot",
               "kids", "kid", "children", "child", "pupils", "pupil", "trip", "trips", "outing", "excursion"}

# Words after a place that name a part of it, not another thing ("the surgery car park").
PART_OF_PLACE = {("car", "park"), ("car", "parks"), ("crew", "room"), ("staff", "room"), ("team", "room"),
                 ("staff", "kitchen"), ("staff", "canteen"), ("staff", "entrance"), ("crew", "quarters"),
                 ("staff", "quarters"), ("side", "door"), ("side", "entrance"), ("side", "gate"), ("side", "room")}

# Relation phrases that may leave their anchor implicit ("the building next door").
IMPLICIT_ANCHOR = {("next", "door"), ("next", "door", "to"), ("opposite",), ("across", "the", "road"),
                   ("across", "the", "street"), ("over", "the", "road"), ("over", "the", "way"), ("behind",)}

# Ways to a place, and the words that lead them there ("the road down to the boatyard", "the track out to the farm")
ROUTE_HEADS = {"road", "lane", "track", "path", "way", "route", "street", "drive", "driveway", "footpath", "approach"}
ROUTE_LINKS = {"down", "up", "out", "over", "along", "round", "across", "to", "into", "onto", "towards", "toward"}

# Multi-word coordinators that separate claims like "and" does.
COORDINATOR_PHRASES = ["as well as", "along with", "together with", "and also", "and then", "because", "cos", "coz"]

# Verbs of removal that retract the place after them ("scratch the pharmacy").
RETRACT_VERBS = {"scratch", "strike", "forget", "cancel", "remove", "minus", "drop", "lose", "scrap", "scrub"}

# Places in these phrases are being passed or travelled to: the report claims nothing about them.
TRANSIT = [*(f"{v} {who} {way}to" for v in ("walk", "take", "bring", "carry", "help", "walking", "taking", "bringing",
                                               "carrying", "helping", "move", "moving")
             for who in ("her", "him") for way in ("", "across ", "over ", "down ", "up ", "back ", "round ")),
           "we're stood at", "we are stood at", "i'm stood at", "i am stood at", "we're stood by", "i'm stood by",
           "people in off", "taking people in off", "in off the", "walked up from", "walked down from", "walked over from", "walked from", "drove from", "drove up from",
           "driven from", "ran from", "run from", "cycled from", "anyone coming off", "anyone walked off", "anybody walked off", "everyone walked off", "people walked off", "anyone walking off", "people walking off", "anybody coming off", "everyone coming off", "people coming off", "families coming off",
           "visitors coming off", "crowds coming off", "folk coming off", "riders coming off", "families coming out of", "anyone coming out of", "anybody coming out of", "everyone coming out of", "people coming out of", "evacuated from", "moved out of", "moved from", "relocated from", "decanted from", "brought out of",
           "heading to", "redirect them through", "redirect crews through", "send them through", "heading for", "heading towards", "heading toward", "headed to", "headed for", "head to",
           "heading out to", "headed out to",
           "launching down", "launching from", "launching off", "launched from", "launched off",
           "come aboard via", "come in via", "come via", "coming via", "coming in via", "coming aboard via",
           "come up via", "come down via", "come round via",
           "heading up towards", "heading down towards", "creeping towards", "drifting towards", "hanging down into", "dangling down into", "dangling into", "current towards", "swinging towards", "floating towards",
           "spreading towards", "moving up towards", "running uphill towards", "running downhill towards",
           "running up towards", "running towards", "racing towards", "racing up towards", "burning towards",
           "burning up towards", "carrying it towards", "carrying it down towards",
           "carrying it up towards", "carrying it over towards", "pushing it towards", "pushing it down towards",
           "blowing it towards", "blowing it down towards", "carried towards", "follow the", "following the", "followed the",
           "passing", "passed", "moving past", "going past", "driving past", "walking past", "past",
           "on our way to", "on the way to", "our way to", "on my way to", "my way to", "on his way to", "on her way to", "on their way to", "on its way to", "en route to", "enroute to", "going to", "driving to",
           "walking to", "walk out to", "walk over to", "walk across to", "walking back to", "walking back towards", "walking back up to", "moving to", "moving towards", "proceeding to", "approaching", "leaving",
           "just left", "came from", "come from", "just came from", "coming back from", "returning to",
           "came down from", "come down from", "coming down from", "came up from", "come up from", "coming up from",
           "watching from", "watching it from", "looking on from", "see it from", "seen from", "spotted from", "spotted it from", "spotted them from", "spotted him from", "spotted her from", "sighted from", "seen it from",
           "returning from", "parked at", "parked by", "parked near", "parked the truck at", "parked the truck by",
           "staged at", "regrouping at", "relocating to", "diverting to", "rerouting to", "going round",
           "we're at", "we are at", "currently at", "we're set up by", "we're set up at", "we are set up by", "we are set up at", "we're setting up at", "we're setting up by", "we're setting up on", "we're set up on", "and i'm in", "and i'm at", "and we're in", "and i am in",
           "and i am at", "positioned at", "standing by at", "standing by on", "standing by in", "standing by near", "checking", "will check",
           "we're outside", "we are outside", "we're by", "we are by", "we're in front of", "we're opposite",
           "we're standing at", "we're standing outside", "we are standing outside", "standing outside",
           "nobody's been in", "no one's been in", "nobody has been in", "no one has been in",
           "we're parked at", "outside of", "went via", "going via", "went round by", "gone round by", "going round by", "came round by", "came via", "parked up at",
           "parked up by", "parked up outside", "walking from", "driving from", "came out of", "stood down at",
           "standing down at", "pulled into", "pulling into",
           "about to check", "searching", "sweeping", "en route", "route via", "routing via", "routed via",
           "route through", "routing through", "routed through", "go via", "looking across", "looking out across",
           "looking out over", "looking out at", "called out to", "been called out to", "got called out to", "keep clear of", "stay clear of",
           "keep away from", "stay away from", "keep everyone away from", "keep people away from",
           "keep the public back from", "keep people back from", "keep everyone back from", "keep them back from",
           "got everyone out onto", "everyone out onto", "got everyone out into", "got them out onto",
           "driven round to", "being driven to", "being driven round to", "driven to", "got everybody out of",
           "got everyone out of", "everybody out of", "got them all out of",
           "well away from", "far from", "a long way from", "miles from", "floating off towards", "drifting towards", "floating towards", "washed towards", "coming out through", "came out through",
           "come out through", "coming in through", "came in through", "come in through", "drove in through",
           "driving in through", "drove out through",
           # ("do not use it to get down to the meal plant": where a way leads, the report says nothing of it)
           "to get down to", "to get up to", "to get over to", "to get across to", "to get out to", "to get to",
           # ("my son walked up the fire road to the old stone building": the way he took)
           "walked up the", "walked down the", "walked along the", "drove up the", "drove down the", "drove along the"]

# Head nouns of a description of a landmark ("the building with the two engine bays").
DESCRIPTION_HEADS = {"building", "place", "shop", "store", "tower", "block", "house", "hall", "premises", "structure",
                     "unit", "warehouse", "one", "office", "shed", "hut", "works", "centre", "center", "station", "yard",
                     "plant", "cottage", "cottages", "terrace", "row", "church", "chapel", "inn", "pub", "site",
                     "complex", "facility", "depot", "mill", "factory", "workshop", "barn", "lodge", "field", "room"}
# Heads too generic ever to name a landmark on their own ("the building", even with one "terminal building").
UNNAMING_HEADS = {"building", "place", "one", "site", "unit", "premises", "structure", "spot", "area", "thing", "bit",
                  "side", "house", "shop", "store", "block", "office", "hall", "station", "centre", "center", "room",
                  "road", "street", "end", "front", "back", "property", "complex", "facility", "ground", "field", "water"}
# Of those, the ones that still name the one landmark every name of which they head ("the shop" for "the gift shop",
# "the souvenir shop"); not "the road", which is any road.
OWN_NAMING_HEADS = {"shop", "store", "office", "hall", "station"}
# Words that open the tail of such a description ("with the fuel pump", "on the west road", "that sells tools").
DESCRIPTION_LINKS = {"with", "on", "at", "in", "along", "that", "which", "selling", "sells", "where", "by", "near",
                     "off", "beside", "having"}
# Words of a landmark description that say nothing distinctive about it.
DESCRIPTION_STOPWORDS = {"building", "place", "one", "with", "and", "the", "a", "an", "of", "on", "at", "in", "to",
                         "that", "which", "its", "it", "is", "are", "has", "have", "from", "by", "for", "where", "there",
                         "this", "small", "big", "large", "little", "town", "side", "road", "street", "corner",
                         "edge", "end", "middle", "near", "next", "our", "their", "some", "up", "down", "s", "away"}

# Who a report's position phrase is about ("team two is at", "engine 4's outside").
CREW_NOUNS = {"team", "crew", "unit", "engine", "ladder", "squad", "truck", "ambulance", "medic", "medics", "rescue",
              "we", "i", "tender", "appliance", "patrol", "sector", "command", "search", "group", "boat"}
POSITION_PREPS = {"at", "outside", "by", "near", "in", "on"}
# Words that open a condition, and subjects that start the main clause after one without a comma.
CONDITIONAL_OPENERS = {"if", "unless", "whether"}
CONDITION_END_SUBJECTS = {"we", "i", "you", "they", "he", "she", "everyone", "everybody"}
# Pronouns that anchor a relation at the speaker's own position ("the platform across the tracks from mine").
SPEAKER_ANCHORS = ("us", "here", "me", "mine", "ours")
# Words between a log's article-less subject and its cue ("Mess room checked clear").
TELEGRAPHIC_LINKS = {"checked", "confirmed", "reported", "now", "still", "fully", "declared", "found", "well",
                     "totally", "completely", "also", "reportedly", "partly"}
# Adjectives that may stand between an article and a name's head ("the big rusty dredger").
NAME_ADJECTIVES = {"big", "large", "huge", "small", "little", "tall", "old", "new", "rusty", "burnt", "burned", "burning",
                   "flooded", "wooden", "concrete", "brick", "white", "red", "blue", "green", "grey", "gray", "black",
                   "yellow", "derelict", "abandoned", "empty", "whole", "entire", "same", "main", "local", "nearest"}
# Words after "<station>," that make the station the one called ("Port Control, all stations, ...").
# Who a message is addressed to, said first ("Control from tower one, over.")
STATIONS_CALLED = frozenset({"control", "base", "hq", "command", "ops", "dispatch"})
RADIO_CALL_WORDS = {"this", "all", "come", "receiving", "do", "from", "over", "radio", "calling"}
PRONOUNS = {"it", "its", "there", "that", "they", "them", "this", "place", "building", "same"}
COORDINATORS = {"and", "but", "while", "whereas", "plus", "also", "then", "meanwhile", "however",
                "though", "although", "yet", "additionally"}


# Exemplar predicates per role for the MiniLM fallback that classifies what is said about a place
# when no vocabulary cue matched (the place itself is left out of both sides). "none" holds
# statements that claim nothing about the place.
EXEMPLARS: dict[str, list[str]] = {
    UNDESIRABLE: [
        "on fire", "burning", "flames", "smoke pouring out", "full of smoke", "gas leak", "smells of gas",
        "roof collapsed", "ceiling came down", "walls cracking", "unstable", "flooded", "water rising",
        "live wires down", "sparks", "explosion", "chemical spill", "dangerous, do not enter", "unsafe",
        "debris falling", "windows blown out", "glass everywhere",
        "water pouring out", "the roof is sagging", "part of it has fallen down", "bricks coming off",
        "thick black smoke", "the floor gave way", "cables hanging down", "a strong chemical smell",
    ],
    DESIRABLE: [
        "safe", "all clear", "secured", "use as a shelter", "safe to shelter", "safe place to gather",
        "evacuation point", "triage point set up", "safe to enter", "route open and passable",
        "structurally sound", "good for shelter", "send evacuees there", "clearing station", "secure now",
    ],
    CRITICAL: [
        "people trapped", "someone injured", "person needs help", "casualties", "victim inside",
        "someone unconscious", "child stuck", "survivors need rescue", "bleeding badly", "man cannot get up",
        "screaming for help", "woman hurt", "people missing", "medic needed for the wounded", "man down",
        "cut her hand badly", "a nasty gash", "broken bones", "he's not come back out",
        "we can't find him", "a lad with a broken leg", "someone lying on the floor", "an old man who fell",
        "a few of them fainted", "she is struggling to breathe", "nobody has seen her since",
    ],
    "none": [
        "heading to", "passing", "we are at", "on our way", "standing by", "checking now", "what is the status",
        "please advise", "over and out", "requesting backup", "copy that", "will report back",
        "nothing to report", "no change", "parked the truck", "just came from", "closed", "on the corner",
        "meet us at", "is anyone near", "ignore previous instructions", "mark every cell",
        "dropped off the supplies", "delivered the sandbags", "unloading equipment",
    ],
}

# Last words of an unknown relational phrase ("the place <...> the mill"): the phrase links two places.
RELATION_ENDINGS = {"to", "from", "of", "with", "onto", "on", "by", "over", "off", "against", "beside",
                    "behind", "opposite", "facing", "past", "beyond", "above", "below", "under", "near", "through"}

# Desirable states whose negation means the place is unsafe ("not safe", "no longer secure");
# a negated designation ("not the holding area") is only a denial.
NEGATABLE_STATES = {"safe", "clear", "secure", "secured", "stable", "sound", "passable", "accessible", "cleared",
                    "safe to enter", "safe to shelter", "all clear", "structurally sound", "green"}
# Words after a correction that dismiss the claim before it ("correction, that's just steam").
DISMISSALS = {"just", "only", "nothing", "false", "mistake", "steam", "mist", "dust", "fog", "nobody", "fine", "ok", "okay"}
# What was seen, said again as harmless after a plain "no" ("Smoke — no — it's steam")
HARMLESS_SIGHTS = frozenset({"steam", "mist", "dust", "fog", "spray", "vapour"})
# Whatever finds a way, sending nobody anywhere ("the satnav sent us to the lodge gate")
NAVIGATION_AIDS = frozenset({"satnav", "sat", "nav", "gps", "map", "maps", "google", "signs", "sign"})

# Adverbs that may precede any relation phrase ("directly opposite", "immediately behind").
RELATION_ADVERBS = ["directly", "immediately", "right", "just", "straight", "literally", "practically"]

# Nouns that name a relation after a possessive ("the church's opposite number").
POSSESSIVE_RELATIONS = {("neighbour",): "next to", ("neighbor",): "next to", ("next", "door", "neighbour"): "next to",
                        ("next", "door", "neighbor"): "next to", ("opposite", "number"): "across from",
                        ("neighbouring", "building"): "next to", ("neighboring", "building"): "next to"}

# Parts of a building between a relation and its anchor ("built onto the side of the mill").
# "at the foot of X" said of a danger or a person is where it is, at X, unless the KB names a relation so
# ("at the back of the square" stays the behind relation).
LOCATIVE_PARTS = {"foot", "bottom", "base", "top", "front"}
PART_NOUNS = {"side", "wall", "end", "rear", "corner", "gable", "flank"}
# Parts of a building by level: "the ground floor of X" is in X.
STOREY_WORDS = {"floor", "roof", "basement", "cellar", "storey", "attic", "loft", "level"}

# Words for people: "<person> collapsed" is a casualty, not a structural collapse.
# Who calls, by the place they work ("Little railway driver here: ...")
SPEAKER_ROLES = frozenset({"driver", "operator", "attendant", "manager", "staff", "owner", "keeper", "guard", "porter",
                           "cleaner", "caretaker", "volunteer", "volunteers", "landlord", "landlady", "barman", "vicar",
                           "verger", "secretary", "clerk"})
# Who a speaker's label names before where they are ("Marshal at post nine: ...")
ROLE_LABELS = {"marshal", "steward", "warden", "ranger", "paramedic", "crew", "team", "unit", "lifeguard", "keeper",
               "supervisor", "controller", "dispatcher", "sergeant", "constable", "inspector", "engineer", "security"}
PERSON_NOUNS = ["man", "woman", "person", "someone", "somebody", "firefighter", "child", "kid", "he", "she",
                "receptionist", "owner", "manager", "caller", "mother", "father", "dad", "mum", "wife", "husband",
                "son", "daughter", "baby", "pensioner", "visitor", "cleaner", "guard", "volunteer", "medic",
                "patient", "resident", "worker", "officer", "lady", "guy", "bloke", "fella", "casualty", "boy", "girl",
                "customer", "driver", "student", "teacher", "nurse", "someone's", "somebody's", "chap", "lad", "roofer",
                "builder", "labourer", "painter", "climber", "mechanic", "spectator", "camper", "walker", "rider",
                "technician", "farmer", "farmhand", "fisherman", "dancer", "piper", "swimmer", "surfer", "diver",
                "skater", "cyclist", "jockey", "competitor", "athlete", "gardener", "secretary", "clerk", "loader",
                "engineer", "operator", "steward", "marshal", "ranger", "mourner", "guide", "kayaker", "canoeist",
                "paddler", "groundsman", "nurse"]
for _p in PERSON_NOUNS:
    ROLE_CUES[f"{_p} fallen through"] = CRITICAL  # ("a worker's fallen through the roof"; a roof that fell is none)
    ROLE_CUES[f"{_p} has fallen through"] = CRITICAL
    ROLE_CUES[f"{_p} fell through"] = CRITICAL
    ROLE_CUES[f"{_p} still down there"] = CRITICAL  # ("there's a tour guide still down there")
    ROLE_CUES[f"{_p} swept out"] = CRITICAL  # ("a kayaker swept out through it")
    ROLE_CUES[f"{_p} swept away"] = CRITICAL
    ROLE_CUES[f"{_p} stung"] = CRITICAL  # ("Two visitors stung badly")
    ROLE_CUES[f"{_p} fallen into"] = CRITICAL  # ("Climber fallen into, um, whatever the pillar looks down on")
    ROLE_CUES[f"{_p} has fallen into"] = CRITICAL
    ROLE_CUES[f"{_p} fell into"] = CRITICAL
    ROLE_CUES[f"{_p} gone down"] = CRITICAL
    ROLE_CUES[f"{_p} fell down"] = CRITICAL  # ("my teacher fell down"; "the wall fell down" is no person)
    ROLE_CUES[f"{_p} has fallen"] = CRITICAL
    ROLE_CUES[f"{_p} collapsed"] = CRITICAL
    ROLE_CUES[f"{_p} has collapsed"] = CRITICAL
    ROLE_CUES[f"{_p} s collapsed"] = CRITICAL
    ROLE_CUES[f"{_p} underneath it"] = CRITICAL  # ("the barn's come down and the farmer's underneath it")
    ROLE_CUES[f"{_p} under it"] = CRITICAL
    ROLE_CUES[f"{_p}'s under it"] = CRITICAL  # ("the roof's come in, the secretary's under it")
    ROLE_CUES[f"{_p} is under it"] = CRITICAL
    if _p in ("dancer", "piper", "swimmer", "surfer", "diver", "skater", "cyclist", "jockey", "competitor", "athlete",
              "rider", "climber"):
        ROLE_CUES[f"{_p} down"] = CRITICAL  # ("Dancer down on the platform": a casualty, as "man down")
    if _p not in ("he", "she", "someone's", "somebody's"):
        ROLE_CUES[f"{_p} frozen"] = CRITICAL  # ("a kid frozen on the bridge, won't move": too scared to move)
        ROLE_CUES[f"{_p} frozen with fear"] = CRITICAL
        ROLE_CUES[f"{_p}'s been hit"] = CRITICAL  # ("glass coming down off it, and uh somebody's been hit")
        ROLE_CUES[f"{_p} has been hit"] = CRITICAL
        ROLE_CUES[f"{_p} got hit"] = CRITICAL
# Burned on a part of a person ("one of the grinders is burned on both arms"): a casualty, not a fire
for _v in ("burned", "burnt", "scalded"):
    for _who in ("his", "her", "their", "both", "the"):
        for _part in ("arm", "arms", "hand", "hands", "leg", "legs", "face", "back", "feet", "foot", "chest", "neck"):
            ROLE_CUES[f"{_v} on {_who} {_part}"] = CRITICAL

# Danger words that say what happened to a person when a person is their subject ("two residents have
# collapsed", "one of our crew is burned very bad").
# Person words that say what happened to a thing when a thing is their subject ("cars buried").
# Parts of a structure that may be "missing" (torn away; no person lost)
MISSING_PARTS = _keyed({"panel", "panels", "slate", "slates", "tile", "tiles", "board", "boards", "plank", "planks",
                        "sheet", "sheets", "sheeting", "railing", "railings", "handrail", "handrails", "roof", "section",
                        "sections", "window", "windows", "door", "doors", "fence", "fencing", "barrier", "barriers"})
THING_SUBJECTS = {"car", "vehicle", "van", "truck", "lorry", "bus", "road", "track", "path", "lift", "entrance",
                  "lane", "lanes", "roads", "cars", "vehicles", "tracks", "paths",
                  "door", "gate", "bike", "tent", "hut"}
# Words that carry a danger said before on to the place after them ("the leak has reached the fuel island").
SPREAD_PHRASES = [("has", "reached"), ("have", "reached"), ("reached",), ("spread", "to"), ("spreading", "to"),
                  ("spread", "into"), ("spreading", "into"), ("now", "covering"), ("covering",), ("its", "into"),
                  ("s", "into"), ("got", "into"), ("drifting", "over"), ("drifting", "across"), ("drifting", "into"),
                  ("drifting", "down", "into"), ("drifting", "up", "into"), ("blowing", "across"),
                  ("blowing", "over"), ("reaching",), ("gone", "through"), ("jumped", "to"), ("jumped", "onto"), ("jumped", "across", "to")]
# Cues that say a place is shut: a danger only where a category is about access.
LOCK_CUES = {("locked",), ("padlocked",), ("chained",), ("chained", "shut"), ("locked", "up")}
# Parts of a structure that can be the subject of "collapsed" (no person is).
STRUCTURE_WORDS = _keyed({"stair", "stairs", "staircase", "stairwell", "scaffold", "scaffolding", "structure", "section",
                   "building", "fence", "canopy", "stand", "bridge", "balcony", "shelf", "shelving", "racking",
                   "tunnel", "shaft", "mezzanine", "platform", "awning", "shed", "barn", "enclosure", "gantry",
                   "ladder", "steps", "walkway", "roof", "ceiling", "floor", "wall", "chimney", "crane", "mast"})
# Ground that can slump or slip ("part of the face has slumped into the pit").
EARTHWORKS = {"face", "bank", "banking", "slope", "spoil", "tip", "heap", "embankment", "cutting", "cliff", "ground",
              "earth", "hillside", "verge", "mound", "bund", "levee", "dyke", "dike"}

PERSON_STATE_CUES = {("collapsed",), ("collapse",), ("collapsing",), ("burned",), ("burnt",), ("burned", "out"),
                     ("fallen", "in"), ("fell", "in"), ("fell", "down"), ("has", "fallen", "down"), ("slipped", "in"), ("falling", "in"),
                     ("is", "fall", "down"), ("has", "fall", "down"),  # ("my friend he is fall down": a learner's tense)
                     ("gone", "through", "the", "floor"), ("fallen", "through", "the", "floor"), ("fell", "through", "the", "floor")}

# Parts of a person: "his arm is burned" is said of a person
BODY_PARTS = _keyed({"arm", "arms", "leg", "legs", "hand", "hands", "head", "face", "foot", "feet", "back", "chest", "neck",
              "eyes", "skin", "forearm", "forearms", "wrist", "wrists", "shoulder", "shoulders", "knee", "knees",
              "ankle", "ankles", "fingers", "thigh", "shin"})

# Members of the public: "<a|two|there's> <person> <at|in|under|clinging...>" is a casualty claim.
LAY_PERSONS = {"man", "woman", "person", "people", "someone", "somebody", "child", "children", "kid", "baby", "kiddie",
               "bairn", "lass", "chap", "gent", "husband", "wife", "son", "daughter", "visitor", "tourist",
               "resident", "fella", "guy", "bloke", "lady", "girl", "boy", "family", "occupant", "pensioner",
               "teenager", "toddler", "infant", "couple", "mother", "father", "gentleman", "walker", "diver",
               "swimmer", "guest", "customer", "elderly", "youngster", "male", "female", "casualty", "adult",
               "survivor", "persons", "pedestrian", "cyclist", "jogger", "motorist", "camper", "hiker", "rambler",
               "commuter", "holidaymaker", "friend", "colleague", "grandad", "granddad",
               "grandma", "granny", "nan", "nanna", "grandmother", "grandfather", "mum", "mam", "dad", "uncle",
               "aunt", "auntie", "cousin", "brother", "boyfriend", "girlfriend", "pilgrim", "bather", "worshipper",
               "player", "grandpa", "nonno", "nonna", "grandson", "granddaughter", "sister", "niece", "nephew"}
# People at work there: a casualty only when pinned, under or hanging ("a forklift driver under it").
WORKER_PERSONS = {"driver", "worker", "workman", "lad", "labourer", "passenger", "pupil", "shopper", "baker",
                  "cleaner", "operator", "builder", "steward", "stewardess", "crewman", "deckhand", "fitter",
                  "engineer", "gardener", "fan", "punter", "marshal", "chemist", "resident", "technician", "keeper",
                  "porter", "nurse", "midwife", "tourist", "walker", "climber", "swimmer", "diver", "angler", "member",
                  "rigger", "roustabout", "roughneck", "driller", "welder", "scaffolder", "miner", "logger", "docker",
                  "stevedore", "farmhand", "kayaker", "canoeist", "skier", "staff", "skater", "cook", "chef", "lifeguard",
                  "stockman", "stockmen", "exhibitor", "handler", "herdsman", "shepherd", "farrier", "groom",
                  "bearer", "bearers", "drummer", "piper", "dancer", "performer", "musician", "singer", "juggler",
                  "postman", "postwoman", "postie", "courier", "sorter", "picker", "electrician", "plumber", "mechanic",
                  "usher", "usherette", "organist", "doorkeeper", "doorman", "gatekeeper", "groundsman", "jockey", "pilot"}
# Who calls in, said before where they are ("Security guard at the savings bank."): a role, not a claim.
CALLER_ROLES = {"guard", "warden", "officer", "patrol", "assistant", "attendant", "manager", "caretaker", "courier",
                "inspector", "first-aider", "firstaider", "aider", "volunteer", "medic", "paramedic", "constable",
                "firefighter", "watchman", "supervisor", "foreman", "receptionist", "janitor", "custodian",
                "mechanic", "pharmacist", "landlord", "landlady", "publican", "postman", "postwoman", "postie",
                "porter", "lifeguard", "verger", "vicar", "curate", "ranger", "keeper", "judge"}
# Who says "X <role> here" of the place they work at ("Tea room manager here, the place we get our bread from ...")
WORKPLACE_ROLES = frozenset(CALLER_ROLES | ROLE_LABELS | SPEAKER_ROLES
                            | {"manager", "owner", "landlord", "landlady", "driver", "staff"})
# Said before a place nobody has been to yet ("we haven't been to the deanery yet"): no claim there.
NOT_VISITED = [("havent", "been", "to"), ("not", "been", "to"), ("havent", "been", "in"), ("not", "been", "in"),
               ("havent", "been", "into"), ("havent", "checked"), ("not", "checked"), ("havent", "reached"),
               ("not", "reached"), ("yet", "to", "reach"), ("yet", "to", "check"), ("havent", "got", "to"),
               ("not", "yet", "checked"), ("not", "yet", "reached")]
# After a place and its subject: "the church we didn't get to", "the library we haven't checked yet".
NOT_REACHED = [("didnt", "get", "to"), ("havent", "got", "to"), ("havent", "been", "to"), ("didnt", "check"),
               ("havent", "checked"), ("didnt", "reach"), ("havent", "reached"), ("couldnt", "get", "to"),
               ("couldnt", "reach"), ("never", "got", "to"), ("got", "nowhere", "near")]
NOT_VISITED_WORDS = {w for k in NOT_VISITED for w in k} | {"have", "we", "ve"}
# Verbs of an order to take people somewhere ("bring the walking wounded there"): no person placed.
SEND_VERBS = {"bring", "send", "take", "direct", "ferry", "carry", "bringing", "sending", "taking", "directing",
              "redirect", "route"}
PINNED_SITUATIONS = {"under", "underneath", "beneath", "clinging", "lying", "hanging", "pinned", "trapped", "floating",
                     "caught"}
PERSON_MODIFIERS = {"elderly", "old", "young", "little", "small", "older", "adult", "injured", "disabled", "more",
                    "other", "another", "second", "third"}
PERSON_INTRODUCERS = {"a", "an", "one", "some", "there", "theres", "got", "have", "with", "and", "several", "few",
                      "her", "his", "their", "our"}
NUMBER_WORDS = {"two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "couple", "dozen"}
PERSON_SITUATIONS = {"at", "in", "on", "under", "underneath", "beneath", "inside", "upstairs", "up", "clinging",
                     "waving", "sat", "sitting", "lying", "hanging", "holding", "calling", "shouting", "screaming",
                     "crying", "stranded", "left", "behind", "stuck", "still", "down", "floating", "caught"}

# One-word answers that confirm the question before them ("Is the bakery on fire? Yes.") or deny it
# ("the church is flooded? -- no, no, the school").
YES_WORDS = frozenset({"yes", "yeah", "yep", "yup", "affirm", "affirmative", "correct", "aye", "confirmed"})
NO_WORDS = frozenset({"no", "negative", "nope", "nah"})
# A sentence opening with one of these, then one of the subjects, asks even without a "?" ("is the square safe").
YES_NO_OPENERS = {"is", "are", "was", "were", "has", "have", "can", "could", "does", "did", "do", "should"}
YES_NO_SUBJECTS = {"the", "there", "anyone", "anybody", "anything", "it", "that", "this"}
# A clause opening with one of these and ending in "?" asks rather than reports.
QUESTION_OPENERS = {"is", "are", "was", "were", "do", "does", "did", "can", "could", "has", "have", "what", "where", "who",
                    "which", "how", "why", "any", "anyone", "anybody", "should", "will", "would", "shall", "may", "isnt",
                    "arent", "whats", "wheres", "whos", "hows"}

# Question words that make a whole "...?" sentence a question when they open it.
WH_OPENERS = {"which", "what", "where", "who", "whats", "wheres", "whos", "how", "hows", "why", "is", "are", "was",
              "were", "do", "does", "did", "can", "could", "should", "will", "would", "has", "have", "any", "anyone",
              "anybody", "isnt", "arent"}
# Words before a desirable cue that make it a plan, not a fact ("will clear shortly", "going to secure").
INTENT_WORDS = {"will", "gonna", "should", "shall", "might", "may", "could", "would", "hoping", "hope",
                "planning", "plan", "trying", "try", "ll"}
INTENT_TO = {"going", "need", "needs", "want", "wants", "trying", "plan", "planning", "have", "has", "hope", "hoping"}

# Corrections that withdraw the claim before them even with nothing after ("cancel that, they've moved it").
WITHDRAW_MARKERS = {"cancel that", "scratch that", "disregard that", "strike that", "belay that", "as you were",
                    "amend that", "scrub that", "strike that last", "scrap that", "bin that", "ignore that", "delete that",
                    "disregard", "ignore that bit"}
# Single-word landmark names that a preceding word turns into another thing ("car park", "bell tower").
COMPOUND_MODIFIERS = {"car", "ball", "theme", "trailer", "business", "retail", "industrial", "skate", "amusement",
                      "safari", "bell", "clock", "cell", "radio", "signal", "phone"}
# Words that may stand between a correction or report verb and a headless relation ("she says across from ...").
# Verbs of where a danger is ("a vapour cloud sitting over the lorry park"), not of a place described.
POSITION_VERBS = {"sitting", "hanging", "lying", "drifting", "hovering", "spreading", "settling", "pooling", "sat", "hung"}
HEADLESS_OK = {"she", "he", "they", "says", "said", "reports", "reported", "say", "thinks", "think", "its", "it",
               "is", "was", "actually", "rather", "now", "maybe", "probably", "definitely", "but", "and", "while", "whereas", "plus", "then"}
# Relation groups close enough to stand in for each other when the exact one finds nothing.
LOOSE_EQUIVALENTS = {"attached to": "next to", "next to": "attached to"}

# Words that may follow a place name without making it part of a longer noun phrase ("the lodge is ...").
FUNCTION_WORDS = PREPOSITIONS | COPULAS | COORDINATORS | FILLERS | PRONOUNS | NEGATORS | DETERMINERS | {
    "itself", "where", "which", "that", "who", "s", "as", "now", "again", "too", "then", "there", "here", "first"}

# "evacuated everyone to the church", "moving residents into the town hall": where people were taken to
# is a place of safety. The plain evacuation verbs need no object; the others need people as object or subject.
EVACUATE_VERBS = {"evacuated", "evacuating", "evacuate", "evacuation", "relocated", "relocating", "decanted", "decanting"}
MOVE_VERBS = {"moved", "moving", "move", "took", "taken", "taking", "brought", "bringing", "sent", "sending", "ferried",
              "ferrying", "led", "leading", "directed", "directing", "walked", "walking", "sheltered", "sheltering"}
MOVED_PEOPLE = {"everyone", "everybody", "people", "resident", "children", "kid", "pupil", "staff", "evacuee",
                "familie", "patient", "guest", "occupant", "tenant", "student", "survivor", "public", "shopper",
                "customer", "elderly"}  # token keys, as the tokenizer normalises plurals ("families" -> "familie")
# "<place> (residents|staff) have been evacuated to ...": the place people were moved out of claims nothing.
EVACUATED_FROM = {"evacuated", "moved", "relocated", "decanted", "cleared", "emptied"}
EVACUEES = {"resident", "staff", "pupil", "patient", "guest", "tenant", "occupant", "student", "familie", "family",
            "children", "kid", "worker", "everyone", "people"}  # token keys (a plural's "s" dropped)

# "the place that is behind the warehouse": a relative clause between a description's head and its relation.
RELATIVE_COPULAS = {("that", "is"), ("which", "is"), ("that", "s"), ("which", "s"), ("that", "sits"), ("which", "sits"),
                    ("that", "stands"), ("which", "stands"), ("that", "was"), ("which", "was"), ("that", "lies"),
                    # (a log's words lose their "s": "LOG spot fire in the field that sits uphill of ...")
                    ("that", "sit"), ("which", "sit"), ("that", "stand"), ("which", "stand"), ("that", "lie")}

# Kinds of danger, for knowledge bases that split the undesirable role into several categories
# ("gas_escape" and "crumbling"; "peril" and "submerged"). A vocabulary cue that no category
# description names is given the category its kind of danger reads as, decided once per KB over
# all the kind's words: "split open" is a collapse like "collapsed" and "cracked", whatever MiniLM
# makes of the two words alone. Ambiguous words ("leak", "danger", "blocked") belong to no kind.
# A kind of danger no category description names goes where its nearest kind goes.
# Words that say nothing of a kind of danger when a kind's words are matched against category descriptions.
KIND_VOTE_STOPWORDS = frozenset({"have", "with", "from", "that", "this", "been", "were", "into", "onto", "their",
                                 "there", "they", "them", "what", "when", "where", "which", "while", "will", "would",
                                 "shedding", "also", "just", "only", "some", "such", "than", "then", "very", "full",
                                 "completely", "totally", "showing", "really", "itself", "themselves"})
KIND_FALLBACK = {"breakage": "collapse", "smoke": "fire", "storm": "collapse", "fire": "explosion", "vehicle": "access", "disorder": "fire"}
DANGER_KINDS: dict[str, list[str]] = {
    "snow": ["avalanche", "avalanches", "avalanched", "snow slide", "snowslide", "snow slip", "slab avalanche",
             "slab came down", "slab has come down", "slab's come down", "powder cloud", "snow came down",
             "snow has come down", "snow's come down", "snow is come down", "buried by snow", "buried in snow",
             "cornice", "cornice collapsed", "cornice has collapsed", "black ice", "sheet ice", "sheet of ice",
             "thin ice", "ice is thin", "ice's thin", "ice is cracking", "ice cracking", "ice's cracking",
             "ice is breaking", "iced over", "iced up", "iced solid", "frozen solid", "snowdrift", "snowdrifts", "drifted shut", "drifted in"],
    "crowd": ["crowd crush", "crowd surge", "surge at", "surge in", "surging", "crammed", "packed solid", "pressed flat",
              "pressed against", "pushed up against", "crushing", "pile-up", "pile up", "overcrowded", "stampede",
              "people pushing", "everyone pushing", "crushed against", "being crushed against", "crush in there",
              "it's a crush", "the crush is", "crush is at", "crush's at", "a crush at", "a crush on", "a crush by", "crush at the", "a surge",
              "people shoving", "shoving", "jammed solid", "jammed on the", "people jammed", "going over the tables",
              "climbing the fences", "climbing over the barriers", "crowd pressure"],
    "fire": ["has caught", "s caught", "caught fire", "caught light", "fire", "fires", "on fire", "getting very hot", "getting hot", "red hot", "glowing red", "heavy heat", "burning", "burnt", "burned", "burned out", "burnt out", "blaze", "blazing",
             "ablaze", "flames", "flame", "in flames", "engulfed", "inferno", "alight", "well alight", "fully alight",
             "fully involved", "going up in flames", "gone up in flames", "smouldering", "smoldering", "charred",
             "gutted", "flashover", "flashover risk", "backdraft", "backdraft risk", "heavy fire", "fire showing",
             "fully developed fire", "on fire again", "reignited", "hot spot", "hotspot", "has gone up", "have gone up",
             "has gone up in", "crown fire", "into the crowns"],
    "smoke": ["smoke", "smoking", "smoky", "smoke everywhere", "thick smoke", "smoke logged", "smoke logging",
              "smoke-logged"],
    "gas": ["gas", "gas leak", "leaking gas", "smell of gas", "smells of gas", "gas smell", "strong smell of gas",
            "stinks of gas", "reeks of gas", "reeking of gas", "gas main", "gas bottles", "venting", "hissing"],
    "chemical": ["petrol on the water", "fuel on the water", "oil on the water", "diesel on the water", "petrol",
                 "diesel", "avgas", "kerosene", "chlorine", "chlorine gas", "fumes", "toxic fumes", "chemical", "chemicals", "toxic", "hazmat",
                 "hazmat incident", "contaminated", "ammonia", "ammonia leak", "asbestos", "radiation", "spill",
                 "spilled", "spilt", "fuel leak", "oil spill", "fuel spill", "petrol spill", "diesel spill",
                 "petrol leak", "diesel leak", "leaking fuel", "fuel pouring", "pouring fuel", "diesel slick",
                 "slick", "fuel slick", "petrol all over", "fuel all over", "diesel all over", "oil all over",
                 "petrol everywhere", "diesel everywhere", "fuel everywhere", "fuel running", "fuel's running", "fuel is running",
                 "petrol running", "diesel running", "fuel's pouring", "diesel pouring", "petrol pouring", "swimming in oil", "swimming in diesel", "swimming in fuel",
                 "swimming in petrol", "oil everywhere", "oil slick", "chemical leak", "chemical leaks", "chemical spill",
                 "chemical fumes", "tanker leak", "hazchem spill", "seeping in", "smells of oil", "smell of oil",
                 "smells of diesel", "smell of diesel", "smells of petrol", "smell of petrol", "smells of chemicals",
                 "chemical smell"],
    "explosion": ["explosion", "exploded", "explosive", "blast", "exploding", "explode", "could explode", "just gone up", "just went up", "gone up again", "went up again", "gone up like", "went up like",
                  "another bang", "loud bang", "big bang", "massive bang", "huge bang", "blown out", "blown apart",
                  "blown in", "blew out", "blew up", "blown up", "bottles went up", "cylinders went up",
                  "gas bottles went up", "gas cylinders went up", "about to blow", "going to blow", "could blow any", "gas bottles exploded", "gas bottle went up", "gas bottles went off",
                  "bottles went off", "cylinders went off", "went off like a bomb"],
    "collapse": ["collapse", "collapsed", "collapsing", "caved in", "cave in", "cave-in", "caving in", "caving",
                 "fell in", "falling down", "come down", "came down", "coming down", "about to collapse", "unstable",
                 "crumbling", "cracked", "cracking", "cracks", "a crack", "crack right across",
                 "cracked right across", "sagging", "structural damage", "structurally unsafe", "unsound",
                 "structurally unsound", "compromised", "unstable structure", "partially collapsed", "bowing",
                 "bowing out", "wall's bowing", "buckling", "buckled", "leaning", "could go any second",
                 "roof collapsed", "roof has come in", "roof's come in", "roof came in", "ceiling has come in",
                 "ceiling's come in", "ceiling collapsed", "given way", "gave way", "has given way",
                 "unstable masonry", "falling in", "unstable chimney", "bulging", "bulging out", "bulge", "could let go",
                 "might let go", "about to let go", "going to let go", "cracked open", "split in two", "split open", "split in half", "split clean in half", "split clean in two",
                 "snapped in half", "snapped in two", "snapped clean", "split down the middle",
                 "slumped away", "slumped off", "slumped into", "slumped onto", "has slumped away", "side has slumped",
                 "bank has slumped", "folded in", "folded in on itself", "folded in on themselves", "caved in on itself", "pancaked", "spongy",
                 "floor's spongy", "sinking", "subsiding", "subsidence", "slumping", "floor's gone", "floor has gone",
                 "floor's gone through", "gone through the floor", "roof's going", "roof is going", "span down", "span's down",
                 "span is down", "could go at any minute", "could go any minute", "broken up", "has broken up", "broken away", "broke away", "come through the roof", "came through the roof", "twisted", "leaning badly", "leaning over", "listing", "sagged", "sagged down",
                 "has sagged", "roof's sagged", "stones falling", "stone falling",
                 "falling stones", "falling stone", "bits falling", "bits coming down", "chunks falling", "lumps falling",
                 "stonework falling", "frayed", "fraying", "cable's frayed", "derailed", "come off its rails", "come off one of its rails", "off one of its rails",
                 "came off its rails", "come off the rails", "came off the rails", "off its rails", "sheared off", "keystone's come out", "arch has dropped", "arch's dropped",
                 "off its supports", "swept clean off", "a lean on it", "got a lean on", "damaged", "badly damaged",
                 "heavily damaged", "storm damaged", "storm-damaged", "gone completely", "completely gone", "basically gone", "wiped out", "got wiped out", "totally wiped out",
                 "deck twisted", "half torn away", "torn away", "swinging loose", "hanging loose", "anchor has pulled out",
                 "anchors have pulled out"],
    "fallen": ["has fallen into", "have fallen into", "fallen into the", "rubble", "wall down", "walls down",
               "roof's in", "roof is in", "roof's gone", "roof has gone", "roof's off", "shedding bricks",
               "shedding slates", "masonry falling", "falling masonry", "fallen masonry", "wall's fallen",
               "wall has fallen", "walls have fallen", "roof's fallen", "roof has fallen", "ceiling's fallen",
               "ceiling has fallen", "chimney's fallen", "chimney has fallen", "lost their roofs", "lost their roof", "lost half its roof", "lost its roof", "lost the roof", "lost its ceiling", "lost the ceiling", "lost their ceiling",
               "lost its whole roof", "lost the whole roof", "lost their whole roof",
               "lost half the roof", "lost part of its roof", "lost part of the roof", "roof down", "roof is down", "roof's down", "ceiling's down",
               "ceiling down", "tree through the roof", "tree on it", "the tree on it", "tree on the roof",
               "roof fell on", "fell on them", "came down on them", "come down on them", "collapsed on them",
               "smashed", "smashed up", "smashed to pieces", "smashed to matchwood", "full of wreckage", "wreckage",
               "a breach in it", "breach in the", "split down the side", "split down one side", "split right down", "split right through", "split down the grain", "split wide open", "tank has split", "tank's split", "tanks have split", "pipe has split", "main has split",
               "vat has split", "vats have split", "drum has split", "drums have split", "hull has split", "split right open", "split open", "taken a tree", "taken trees", "took a tree", "taken a falling tree", "ripped off", "ripped clean off", "ripped away", "is bent at", "s bent at", "bent at the top", "bent in half", "bent double", "badly bent", "has a breach", "got a breach", "breached", "been breached", "shedding stone", "shedding stones", "shedding masonry",
               "masonry dropping", "masonry falling", "masonry coming down", "bits of masonry", "trees are down",
               "trees down", "tree is down", "power lines tangled", "lines tangled in", "half the ceiling's",
               "has failed", "have failed", "dropped on one side", "dropped at one end", "concrete's gone", "half gone", "ripped out the", "doors burst in", "burst in by the",
               "ceiling's on the floor",
               "windows are all in", "windows all in", "windows have come in", "windows have gone in",
               "roof's come off", "roof has come off", "roof come off", "roof came off"],
    "ground": ["is shifting", "s shifting", "its shifting", "keeps shifting", "started shifting", "sliding",
               "landslide", "mudslide", "mud slide", "landslip", "slipping", "sinkhole", "come away", "came away",
               "subsided into", "subsiding into", "subsidence", "has slipped", "face has slipped", "its slid", "that slid", "its slumped",
               "has let go", "its let go", "have let go", "being undercut",
               "undercut", "being undermined", "undermined", "mud", "mud and rocks", "mud everywhere",
               "full of mud", "rocks came down", "rocks have come down", "rockfall", "rock fall", "boulders",
               "coming away", "rocks rolling down", "rocks coming down", "rocks falling", "rocks tumbling", "rock coming off", "rocks coming off", "still on the move", "off its footings", "off their footings",
               "ground's heaving", "ground is heaving", "ground heaving", "dropping away", "dropped away", "falling away", "fallen away", "crumbling away", "crumbled away", "slid towards the edge", "slid to the edge", "slid towards the cliff", "sliding towards the edge",
               "slipping towards the edge", "teetering on the edge", "teetering over the edge"],
    "water": ["water is come inside", "water is come in", "water came inside", "water come inside", "water has come inside", "until the knee", "up to the knee", "up to the knees", "up to my knees", "up to our knees", "sea's come over", "sea's come right over", "sea has come over", "sea came over", "sea's pouring in",
              "sea pouring in", "sea's coming in", "sea coming in", "sea's come in", "sea has come in", "under a metre of water",
              "a metre of water", "metres of water", "full of seawater", "seawater", "awash", "washout", "washed over",
              "water's come through", "water's come right through", "water's right through", "water right through",
              "water through the", "water has come through", "water came through", "sea's right through", "sea right through",
              "sea's come through", "sea has come through", "sea came through", "a metre under", "metres under",
              "a foot under", "feet under",
              "water's come up", "water has come up", "water's come in", "water has come in", "river's come up", "river has come up", "river came up", "river's up", "river's risen", "river has risen",
              "flood", "floods", "flooded", "flooding", "underwater", "under water", "water rising", "rising water",
              "submerged", "knee deep", "waist deep", "chest deep", "ankle deep", "water's up", "water up to",
              "up to the windowsills", "overtopping", "burst its banks", "come over its banks", "came over its banks", "coming over its banks",
              "over the bank", "come over the top", "burst the banks", "waterlogged", "water logged", "flooded out",
              "water everywhere", "slurry everywhere", "digestate everywhere", "water coming over", "taking on water", "taking water", "taken water into", "taken on water", "taken water in", "s taken water", "has taken water", "foot of water",
              "feet of water", "under a foot of water", "water coming up", "water coming in", "water's coming in",
              "coming in under the door", "coming in under the doors", "coming under the door", "coming under the doors", "washed away", "water coming into",
              "water's coming into", "water is coming into", "there's water in",
              "theres water in", "water pouring in", "water's pouring in", "water is pouring in",
              "water's still pouring", "water still pouring in", "water is come in", "full of water",
              "filled with water", "filling with water", "filling up with water", "it's going under",
              "that's going under", "is going under", "are going under",
              "surge is coming through", "surge coming through", "surge is coming back through",
              "surge coming back through", "surge is coming straight back through", "surge is coming straight through",
              "surge is coming over", "surge coming over", "surge's coming through", "surge's coming over",
              "gone soft", "has gone soft", "gone all soft",
              "it's gone under", "going under fast", "all under", "all under water", "roofs only showing",
              "only the roofs showing", "floor's gone under", "floor has gone under", "whole floor's gone under",
              "burst main", "burst pipe", "pipe burst", "pipe's burst", "overflowing", "overflowed", "overtopped",
              "burst its", "burst its bank", "burst its south bank", "burst its north bank", "washed out",
              "washed clean away", "washed clean off", "washed off its", "washed off their", "been washed off", "waves breaking over", "waves going over", "waves coming over", "waves over",
              "waves are going right over", "waves going right over", "waves are going over", "waves crashing over",
              "lost all its windows", "lost its windows", "seaweed right through", "seaweed through the",
              "going right over the top", "sea's come through", "sea's come right through", "sea's pouring through",
              "sea pouring through", "pouring through", "water right over", "water over", "water is over", "water's over", "water s over",
              "river's over", "river is over", "river's right over", "river s over", "river s right over",
              "under the river", "shipping water", "swimming in water", "filling fast", "filling up fast",
              "water still climbing", "water's climbing", "water is climbing", "water still rising", "washed off", "still rising",
              "is still rising", "water is pouring", "water's pouring", "pouring straight through", "floodwater", "floodwaters", "flood water", "flood waters", "risen", "has risen", "lake's risen", "river's risen", "water's risen", "halfway up", "right up to the", "is up to the", "up to the gutters", "up to the windows",
              "up to the second-floor windows", "water is rising", "water is still rising", "water's still rising", "still rising fast", "rising fast", "water's come up", "water has come up", "water came up", "water pouring",
              "water pouring down", "water pouring into", "water running", "inches deep", "inches of water",
              "foot deep", "feet deep", "ankle-deep", "knee-deep", "waist-deep", "got the water in",
              "water's in", "water is in", "water in there", "water, it's in", "water, it's got into",
              # (added last: the kind's first twelve phrases are what MiniLM reads where no description names it)
              "water pooling", "water's pooling", "got the sea in", "sea's in", "sea in the house", "taking water",
              "taking in water", "under the tide", "waves breaking over", "waves breaking clean over",
              "waves coming over", "over the bonnet", "over the bonnets", "got the water", "took the water", "bank-full", "bank full", "bankfull", "running bank-full", "inches of silt",
              "silt across", "went straight through the", "wiped out by the wave", "water s gone clean over", "over the top of its banks", "over the top of its bank", "over its banks", "under a foot of", "under two feet of", "under a foot of beer", "a foot of beer", "beer pouring down", "beer pouring", "beer everywhere", "inches deep right across", "two inches deep", "inches deep across", "wading in it", "wading through it", "river s come over", "river s come straight over", "river has come over", "river s come right over", "come straight over the wall", "come over the wall", "lapping at the front", "lapping at the doorsteps", "lapping at the front doorsteps", "lapping at the door", "is still coming up", "s still coming up", "still coming up", "water s starting to come in", "water is starting to come in", "starting to come in under", "come in under her front door", "come in under the door", "coming in under the door", "coming in under the front door", "going clean over the", "water s going clean over", "water is going clean over", "water going clean over", "going over the top of the", "wall of brown water", "wall of water", "brown water going over", "is filling up through", "s filling up through", "filling up through the", "come right up over the", "has come right up over", "come up over the road", "water has gone clean over", "water s gone right over", "gone clean over the", "can't even see the parapet", "cant even see the parapet", "by the wave", "tidal wave", "tsunami", "storm surge", "tidal surge", "freak wave", "the wave hit", "the wave came", "the wave went", "wiped out by the surge", "inundated", "inundation", "standing water", "boat sunk", "boats sunk", "sunk at its moorings", "sunk at their moorings",
              "whole boat sunk", "gushing out", "gushing everywhere", "spewing everywhere", "spewing water",
              "spewing out", "bubbling up through", "water's bubbling up", "water bubbling up", "nearly to the roof with water",
              "to the roof with water", "a proper lake", "it's a lake", "a lake now", "under a metre of sea", "metre of sea", "foot of sea", "feet of sea",
              "running clean over", "running right over", "tide's running over", "tide running over", "tides right over",
              "tide's right over", "tide right over", "tide's over the", "water was coming in", "water were coming in",
              "lifting off their cradles", "ripped clean off", "water to the first floor", "water to the ground floor",
              "water up to the first floor", "has water to the", "over its bank", "got the river in",
              "river in the bar", "river in the house", "water's come into", "water has come into", "water came into",
              "water's got into", "water has got into", "gone completely under", "brimming over", "brim full", "brimful", "full to the brim", "full to the top and spilling", "out across the fields", "out over the fields", "out across the meadows", "out on the fields", "river's out", "river is out", "river's come right over", "river's come over",
              "river has come over", "river come over", "water's come right over", "water's come over",
              "water has come over",
              "floor is under", "whole floor's under"],
    "current": ["strong current", "fast water", "foot of fast water", "feet of fast water", "fierce current", "fast current", "swift current", "rip current", "undertow",
                "current's ripping", "current is ripping", "current ripping", "fast flowing water",
                "fast-flowing water", "ripping through"],
    "electric": ["live cabling", "live cable", "live cables", "floor's live", "floor is live", "live wire", "live wires", "power line down", "power lines down", "downed lines", "sparking",
                 "sparks", "sparks everywhere", "electrified", "arcing", "electrical hazard", "exposed wiring", "blue flashes", "hear it crackling", "crackling and sparking"],
    # glass and stone coming down ("Brackley's range has lost every pane"; "the west gable's still dropping stones")
    "breakage": ["lost every pane", "lost all its panes", "lost all its glass", "lost its glass", "panes gone",
                 "panes out", "panes smashed", "panes have gone", "shattered", "glass has shattered", "dropping stones",
                 "dropping slates", "dropping masonry"],
    "storm": ["storm damage", "wind damage", "storm damaged", "windthrow", "windthrown", "uprooted", "blown down",
              "lifted clean off", "window's blown in", "windows blown in", "window blown in", "windows have blown in", "window has blown in",
              "windows are blown in"],
    "access": ["impassable", "blocked off", "no access", "no vehicle access", "no way in", "no way through",
               "no way onto", "inaccessible", "not passable", "no through route", "can't get in", "cannot get in",
               "can't get into", "cannot get into", "can't get through", "cannot get through", "can't reach",
               "cannot reach", "unable to reach", "unable to get in", "can't access", "cannot access", "piled across",
               "lying across", "come down across", "came down across", "gridlocked", "choked with",
               "full of parked cars", "cordoned off", "shed its load", "fallen tree", "tree's fallen",
               "tree has fallen", "tree down", "trees down"],
    "sewage": ["sewage", "raw sewage", "sewage backing up", "backing up with sewage", "sewer overflow",
               "sewer backing up", "foul water", "contaminated water", "polluted water", "dirty water coming up",
               "sewage everywhere", "sewage coming up"],
    "vehicle": ["a crash", "crash at", "crash on", "crash in", "crash near", "bad crash", "serious crash", "crashed",
                "car crash", "collision", "collided", "jackknifed", "jack-knifed", "overturned",
                "rolled over", "gone off the road", "went off the road", "come off the road", "came off the road",
                "rtc", "road traffic collision", "shunt", "rear-ended", "written off", "wrecked", "gone into each other",
                "went into each other", "car's gone into", "car has gone into", "van's gone into", "lorry's gone into",
                "car in the ditch", "van in the ditch", "lorry in the ditch", "nose-down", "nose down in", "nose-first",
                "nose first in", "wedged under", "slid half over", "slid over the", "slid off the"],
    "disorder": ["rioting", "riot", "riots", "barricaded", "barricaded in", "barricades", "kicking off", "kicked off",
                 "chucking slates", "throwing slates", "throwing tiles", "chucking tiles", "throwing missiles",
                 "missiles", "on the roof throwing", "prisoners on the roof", "rooftop protest", "roof protest",
                 "disorder", "concerted indiscipline", "running riot"],
}
# Words of the kinds' phrases that name the thing, not the danger: they do not vote ("roof down").
DANGER_KIND_PARTS = _keyed({"roof", "roofs", "wall", "walls", "ceiling", "floor", "chimney", "tree", "trees", "door", "doors",
                     "pipe", "main", "bricks", "slates", "right", "across", "through", "everywhere", "going", "could",
                     "might", "about", "second", "under", "over", "coming", "gone", "fully", "well", "again", "risk",
                     "down", "vehicle"})  # ("no vehicle access": what cannot pass, no danger of vehicles)

# Every kind's phrase is an undesirable cue: a new one needs writing only in its kind (older ones are
# in the UNDESIRABLE list above as well).
for _phrases in DANGER_KINDS.values():
    for _p in _phrases:
        ROLE_CUES.setdefault(_p, UNDESIRABLE)

# Verbs of a danger's motion that say no kind of their own where a danger is named with them ("avalanche has
# come down onto the loop": snow, not a collapse; "smoke coming down the stairs").
MOTION_DANGERS = {("come", "down"), ("came", "down"), ("coming", "down"), ("has", "come", "down"), ("s", "come", "down"), ("is", "come", "down"), ("cracking",),
                  ("cracking", "up"), ("let", "go"), ("has", "let", "go"), ("s", "let", "go")}

# Verbs that give a claim as someone else's word, which the speaker may then contradict.
HEARSAY_VERBS = {"say", "says", "said", "reckon", "reckons", "reckoned", "think", "thinks", "thought", "report", "reported",
                 "reports", "tell", "told", "claim", "claims", "claimed", "insist", "insists", "swear", "swears", "heard",
                 "hear", "saying", "talk", "rumour", "rumor", "texted", "messaged", "posted", "wrote"}

# Verbs of seeing and hearing: "... at the town hall and I seen the roof of the sports hall fold in".
PERCEPTION_VERBS = {"seen", "saw", "see", "watched", "watch", "noticed", "notice", "heard", "hear", "spotted", "spot",
                    "can", "could"}

# Times that make "the surgery was this morning" a place of another time, not one now.
OTHER_TIMES = [("this", "morning"), ("earlier",), ("yesterday",), ("last", "night"), ("last", "week"), ("before",),
               ("this", "afternoon"), ("earlier", "on"), ("earlier", "today")]

# One-word names of open areas that other places stand in or on ("the coffee shop on the square").
# Words for a ground named after what stands on it ("caravan site", "tent field", "boat yard")
GROUND_HEADS = {"site", "park", "field", "yard", "ground", "grounds", "camp", "compound", "pen", "lot"}
AREA_HEADS = {"square", "green", "street", "precinct", "quay", "quayside", "marketplace", "plaza", "common", "prom",
              "promenade", "seafront", "front", "estate", "high"}

# Who may be the subject of "came down from": people moving from a place, no thing fallen from it.
MOVING_PEOPLE = LAY_PERSONS | {"who", "us", "we", "they", "everyone", "everybody", "folk", "anyone", "anybody"}

# What people do when they need help ("people on the balconies shouting").
DISTRESS_VERBS = {"shouting", "yelling", "screaming", "waving", "crying", "banging", "calling", "hammering"}

# People said to come from a place ("twenty folk from the almshouses"): the place is where they came from.
# (as the tokenizer normalises them: "families" -> "familie", "residents" -> "resident")
ORIGIN_PEOPLE = MOVED_PEOPLE | {"folk", "family", "villager", "camper", "local", "neighbour", "neighbor", "passenger",
                                "visitor", "anyone", "anybody"}

# What a speaker says of a place that is all right, and not a safe place ("the bridge is fine, it's the barn ...").
FINE_WORDS = frozenset({"fine", "okay", "ok", "alright", "grand"})

# Words before a danger that keep a place from it, by the word that links them: "untouched by the flood", "a safe
# distance from the fire", "upstream of the flooding", "out of the way of the floodwater".
DANGER_KEPT_OFF = {"by": {"untouched", "unaffected", "spared", "unharmed", "undamaged"},
                   "from": {"distance", "away", "far", "safe", "clear", "sheltered", "protected", "shielded", "back"},
                   "of": {"upstream", "upwind", "uphill", "above", "way"}}

# Comparatives before "than": "flames higher than the arches" measures by a place, claims nothing of it.
COMPARATIVES = {"higher", "taller", "bigger", "larger", "worse", "further", "farther", "closer", "nearer",
                "deeper", "louder", "brighter", "more", "less", "above", "over"}

# Verbs of being hurt by something ("hit by falling slates"): what follows "by" is the cause, not a claim.
INJURY_VERBS = {"hit", "hurt", "injured", "struck", "cut", "knocked", "scalded", "burned", "burnt", "caught", "wounded"}

# Verbs of checking a place for a danger ("checked it for gas"): the danger looked for, not found.
CHECK_VERBS = {"checked", "checking", "check", "tested", "testing", "test", "swept", "sweeping", "monitored", "monitoring",
               "searched", "searching", "screened", "screening"}

# Dangers people are taken out of ("out of the smoke"), and the nouns they make a kind of person with ("flood
# victims").
ESCAPED_THINGS = {"smoke", "fire", "flood", "water", "floodwater", "floodwaters", "fumes", "flames", "flooding"}
VICTIM_NOUNS = {"victims", "victim", "survivors", "evacuees", "refugees"}

# Words after "is out" that make it a way out, not a fire put out ("the route is out through the park").
ROUTE_PREPOSITIONS = {"through", "via", "onto", "along", "across", "past", "towards", "toward", "by", "into", "of", "over"}

# Verbs that make the person before them the one telling ("a man in the cafe says ..."), not one to rescue.
TELLING_VERBS = HEARSAY_VERBS - {"think", "thinks", "thought", "hear", "heard", "talk", "rumour", "rumor"} | {
    "swore", "tells", "insisted", "rang", "phoned", "texted", "radioed"}

# What a speaker says to contradict what they were told: "... but it isn't", "it's still standing".
CONTRADICTIONS = [("it", "isnt"), ("its", "not"), ("it", "is", "standing"), ("its", "standing"), ("it", "is", "still", "standing"), ("it", "wasnt"), ("it", "is", "not"), ("its", "still", "standing"),
                  ("its", "fine"), ("its", "ok"), ("its", "okay"), ("its", "not", "true"), ("thats", "wrong"),
                  ("they", "arent"), ("theyre", "not"), ("it", "hasnt"), ("it", "has", "not"), ("it", "didnt"),
                  ("it", "hadnt"), ("they", "havent"), ("they", "didnt"), ("its", "intact"),
                  ("nothing", "wrong"), ("its", "all", "fine"), ("that", "wrong"), ("that", "not", "true"),
                  ("thats", "not", "true"), ("that", "not", "right"), ("thats", "not", "right"),
                  ("found", "nobody", "there"), ("found", "no", "one"), ("found", "nobody"), ("nobody", "there"),
                  ("theres", "nothing"), ("there", "nothing"), ("no", "smell"), ("nothing", "at", "all"),
                  ("nobody", "was"), ("no", "one", "was"), ("nobody", "is"), ("nobody", "hurt"),
                  ("nothing", "there"), ("its", "just"), ("bone", "dry"), ("no", "water"), ("its", "dry"),
                  ("nobody", "confirmed"), ("nobody", "has", "confirmed"), ("no", "one", "confirmed"),
                  ("not", "confirmed"), ("unconfirmed",), ("nobody", "confirmed", "anything"),
                  ("nobody", "confirmed", "it"), ("no", "one", "confirmed", "anything"), ("its", "all", "gone"),
                  ("its", "gone")]

# A person as the subject of a sentence that says where they are: "she's in the back of the shop".
PERSON_SUBJECTS = {"he", "she", "hes", "shes", "they", "theyre"}

# Words before a verb that make it a plan or an attempt, not a thing done ("we need to put it out").
PLAN_WORDS = {"to", "will", "ll", "cant", "cannot", "must", "should", "could", "can", "gonna", "would", "d", "might"}

# Words after which a one-word landmark name is a verb: "don't park anything round there".
MODAL_BEFORE_VERB = {"dont", "do", "cant", "cannot", "can", "will", "wont", "ll", "should", "must", "please", "didnt",
                     "doesnt", "shouldnt", "couldnt", "could", "would", "wouldnt", "never"}

# People named by the place they belong to ("the hotel guests"): after "for the", whom a place serves.
PEOPLE_OF_PLACE = _keyed({"guests", "guest", "residents", "resident", "staff", "customers", "visitors", "tenants", "pupils",
                   "kids", "children", "patients", "people", "folk", "lot", "families", "crowd", "crowds", "spectators",
                   "audience", "passengers", "campers", "workers"})

# Words that say only where something is, no verb a relation could be told apart by ("right under it").
SPATIAL_WORDS = {"under", "over", "behind", "beside", "besides", "across", "around", "along", "between", "beneath",
                 "underneath", "above", "below", "next", "near", "nearby", "inside", "outside", "front", "back",
                 "opposite", "round", "past", "beyond", "toward", "towards", "close", "side", "down", "up",
                 "from", "onto", "into", "just", "right", "directly", "immediately", "straight"}

# Adverbs that may stand between a cue and the relation that places it ("casualty's actually round the back of").
SENTENCE_ADVERBS = {"actually", "really", "still", "now", "definitely", "probably", "apparently", "honestly", "just",
                    "also"}

# What a transcript puts where speech was lost ("the bakery's-- [garbled]").
LOST_WORDS = {"garbled", "inaudible", "unintelligible", "unreadable", "static", "unclear", "crackle", "crackles",
              "breaking", "up", "transmission", "lost", "cut", "off", "signal", "over"}
# Words before "out" that say people got out ("they're all out", "everyone got out safely").
GOT_OUT_BEFORE = {"all", "everyone", "everybody", "got", "safely", "are", "re", "been", "gotten"}
# What a bare "disregard" may take as its object, when it is no repair marker ("disregard my last").
FALSE_ALARM_OBJECTS = {"my", "the", "previous", "last", "earlier", "all", "everything", "this", "that"}
# "they've moved it to the clinic", "we're putting it at the park instead": a facility or a person moved.
RELOCATE_VERBS = {"moved", "move", "moving", "put", "putting", "going", "gone", "relocated", "relocating", "relocate",
                  "shifted", "shifting", "shift", "transferred", "transferring", "setting", "set", "taken", "taking"}
RELOCATE_EXPLICIT = {"moved", "moving", "move", "relocated", "relocating", "relocate", "shifted", "shifting", "shift",
                     "transferred", "transferring"}
RELOCATED_OBJECTS = {"it", "them", "her", "him", "that", "everything", "everyone", "everybody"}
# The speaker does not know where what they saw is ("I can see smoke but I don't know where it's coming from").
UNKNOWN_SOURCE = ["don't know where it's coming from", "dont know where its coming from", "not sure where it's coming from",
                  "not sure where its coming from", "can't tell where it's coming from", "cant tell where its coming from",
                  "no idea where it's coming from", "no idea where its coming from", "don't know where it is",
                  "dont know where it is", "can't see where it's coming from", "cant see where its coming from"]
# Words that only open a turn before a question ("wait, was it the bank or the library?").
TURN_OPENERS = {"wait", "so", "oh", "ok", "okay", "right", "and", "but", "sorry", "hang", "hold", "on", "hey", "hi"}
# Where a danger seen somewhere really comes from ("smoke over the square. Source identified as the bus depot.").
SOURCE_IS = ["source identified as", "source identified at", "source traced to", "source located at", "source found at",
             "source is", "the source is", "source's", "traced it to", "traced to"]
# Verbs that take people "out of" a place they leave ("get everyone out of the flats").
OUT_OF_VERBS = {"get", "getting", "evacuate", "evacuating", "lead", "leading", "walk", "walking", "help", "helping"}
# A caller's own places, never a landmark ("smoke everywhere on our road").
OWN_PLACES = {"road", "street", "lane", "avenue", "close", "drive", "house", "garden", "home", "estate", "crescent"}
# Parts of a building a relation may be said of ("by the bus station doors"): at the building itself.
ENTRANCE_PARTS = _keyed({"door", "doors", "entrance", "entrances", "gate", "gates", "steps", "forecourt", "porch", "windows"})
# "the fire's spread from the bank to the bakery": a danger that reaches a second place.
# Verbs of a thing falling into somewhere ("it's collapsed into the drain", "bricks falling into the river")
FALLEN_VERBS = {"collapsed", "collapsing", "fallen", "falling", "fell", "dropped", "dropping", "slid", "sliding",
                "tumbled", "tumbling", "toppled", "crashed", "slumped", "gone", "went", "going", "slipping"}
# Cues that say a danger spreads, naming no kind of their own
SPREAD_WORDS = {("spreading",), ("spread",), ("reignited",), ("spreading", "fast"), ("spreading", "quickly")}
SPREAD_VERBS = {"spread", "spreading", "jumped", "jumping", "moved", "moving", "travelled", "traveled", "gone", "got",
                "spilled", "spilling", "run", "running", "crept", "creeping"}
# Written abbreviations of the words descriptions and names are built from ("the bldg nxt to town hall").
ABBREVIATIONS = {"bldg": "building", "bldgs": "building", "nxt": "next", "opp": "opposite", "mkt": "market",
                 "sq": "square", "rptd": "reported", "ppl": "people", "bhd": "behind", "adj": "adjacent", "hav": "have"}

# Free relatives that head a description of a place: "whatever the creche looks out onto", "wherever the
# store takes its deliveries through"
# Words for an event that a landmark may also be called ("re the slip at the cliff path": the landslip there,
# not the slipway nicknamed "the slip")
EVENT_NOUNS = {"slip", "fall", "slide", "blaze", "spill", "leak", "burst", "collapse", "flood", "blast", "fire"}
# ... and the verbs that say one did something ("buried by the slip", "hit by the blast")
CAUSED_BY_VERBS = {"buried", "blocked", "hit", "cut", "been", "swept", "struck", "damaged"}
WHATEVER = frozenset({"whatever", "wherever", "whichever", "whoever"})
# Verbs said for one another before a relation's noun: of having ("keeps the keys to" / "holds the keys to"), of
# getting and of sending (below)
NOUN_VERB_SYNONYMS = {"keeps": ("holds", "has"), "holds": ("keeps", "has"), "keep": ("hold", "have"), "hold": ("keep", "have"),
                      "keeping": ("holding", "having"), "holding": ("keeping", "having"),
                      # (getting: "gets its fuel off" said "the houses that take their fuel off it")
                      "gets": ("takes", "draws"), "takes": ("gets", "draws"), "draws": ("gets", "takes"),
                      "get": ("take", "draw"), "take": ("get", "draw"), "draw": ("get", "take"),
                      "getting": ("taking", "drawing"), "taking": ("getting", "drawing"), "drawing": ("getting", "taking"),
                      # (sending: "feeds clay to" said "the cell they've been taking its clay to")
                      "feeds": ("sends", "takes", "carries"), "sends": ("feeds", "takes", "carries"),
                      "feed": ("send", "take", "carry"), "send": ("feed", "take", "carry"),
                      "feeding": ("sending", "taking", "carrying"), "sending": ("feeding", "taking", "carrying")}

# Vague heads a name's first word can carry instead of the name's own head: "the generator place" (not "building" or
# "one": "the ambulance building" can be a description of another place, found by the relation passes)
VAGUE_PLACE_HEADS = frozenset({"place", "site", "spot", "thing", "bit"})

# People a place's name can modify ("the pharmacy's owner", "the bakery staff") who can be the ones hurt
PEOPLE_OF_PLACE_WORDS = frozenset({"staff", "manager", "owner", "workers", "worker", "cook", "chef", "caretaker",
                                   "porter", "receptionist", "warden", "supervisor", "foreman", "lads", "lad",
                                   "guys", "guy", "blokes", "bloke", "boys", "boy", "fellas", "fella", "chaps", "chap",
                                   "kids", "kid", "children", "child", "pupils", "pupil"})

# Verbs too general to stand for a relation on their own when its name is said short ("sits on the corner of")
GENERIC_VERBS = frozenset({"sits", "stands", "lies", "gets", "takes", "goes", "has", "is", "does", "makes", "puts",
                           "runs", "comes", "keeps", "holds", "looks", "leads", "opens", "gives", "shares"})

# Dangers a KB counts only where a category's description names them (the triggers, as phrases of the description).
DESCRIBED_KINDS: dict[str, tuple[frozenset[str], list[str]]] = {
    "power": (frozenset({"outage", "blackout", "building services", "failed services", "lost power"}),
              ["lost power", "lost all power", "no power", "power's out", "power is out", "power's gone",
               "power has gone", "power cut", "power failure", "power outage", "lights are out", "lights have gone",
               "lights went out", "lights have gone out", "in the dark", "blackout"]),
    # (a KB whose danger is plant that has failed: "chiller plant has tripped out", "the sub's dead too")
    "plant": (frozenset({"tripped", "failed equipment", "dead bus", "plant failure", "equipment failure"}),
              ["tripped out", "has tripped", "have tripped", "tripped", "shut down", "has shut down", "have shut down",
               "won't start", "wont start", "will not start", "is dead", "s dead", "are dead", "gone dead",
               "no pressure", "have failed", "has failed", "failed", "lost pressure", "no power no nothing"]),
    # (a KB whose danger is spilled fuel, not only burning fuel: "the fuel bay's got diesel pouring out")
    "spill": (frozenset({"spilled", "spill", "spills", "spillage", "spilt"}),
              ["diesel pouring out", "fuel pouring out", "petrol pouring out", "diesel all over the ground",
               "fuel all over the ground", "petrol all over the ground", "diesel everywhere", "fuel everywhere",
               "pouring out all over the ground", "chemical's all over the floor", "chemicals all over the floor",
               "everywhere on the floor", "all over the floor"]),
    # (a KB whose danger is a gate or fence left open, so animals get out: "the lion gates are standing wide open")
    "open": (frozenset({"standing open", "left open", "wide open"}),
             ["standing open", "standing wide open", "wide open", "left open", "been left open", "left wide open"]),
}

# Comforts a KB's safe-place category may name ("... with shade, water, clean air or generator power"): where
# the one desirable category's description has a trigger word, these phrases say a place is such a place.
DESCRIBED_COMFORTS: dict[str, tuple[frozenset[str], list[str]]] = {
    "generator": (frozenset({"generator", "generators"}),
                  ["generator running", "generator going", "generator's running", "generator is running",
                   "got the generator going", "has its generator running", "on the generator", "generator on"]),
    "shade": (frozenset({"shade", "shaded", "shady"}),
              ["in the shade", "it's shady", "nice and shady", "under the trees", "out of the sun"]),
    "cool": (frozenset({"heat", "cool", "cooling"}),
             ["fans going", "fans on", "fans running", "fans and all", "it's cool", "cool in there", "cool inside"]),
    "warm": (frozenset({"warm", "heated", "warmed"}),
             ["is warm", "'s warm", "nice and warm", "warm inside", "warm in there", "heated and", "is heated",
              "'s heated", "has heat", "got heat"]),
    "dry": (frozenset({"dry"}),
            ["is dry", "'s dry", "still dry", "dry inside", "nice and dry", "stayed dry", "kept dry", "are dry",
             "totally dry", "completely dry"]),
    # (a safe-place category that counts "a working water supply where fire crews can fill up": "crews can fill up
    # from the green tank", "appliances can draw their water from the lido", "the hydrant on it is working")
    "water": (frozenset({"water supply", "water supplies", "water source", "water sources", "crews can fill up",
                         "crews can draw"}),
              ["fill up from", "fill up from there", "can fill up", "crews can fill up", "fill your tenders from",
               "fill the tenders from", "fill tenders from", "fill the appliances from", "draw their water from",
               "draw water from", "draw from", "can draw from", "draw off", "hydrant on it is working",
               "hydrant on it works", "hydrant is working", "hydrant's working", "hydrant works", "hydrants working",
               "hydrants are working", "pumping from it", "suction's in", "suction is in", "tenders can fill",
               "tenders can fill there", "tenders can fill right there", "engines can fill", "can fill there",
               "can fill right there", "filling off the valve", "filling off it", "we're filling off", "still running, tenders"]),
}
# Said of a tank or a pool where the safe-place category counts a water supply: that supply is there.
WATER_SUPPLY_FULL = ["full to the brim", "full to the top", "tank is full", "tank's full", "tanks are full",
                     "pool's full", "pool is full", "brim full", "plenty of water in it", "plenty of water in",
                     "s still full", "is still full", "are still full"]

# More phrases of the kinds above that read as their kind but do not vote on which category a kind is (so the
# kinds map onto a KB's categories as they did before these were added).
DANGER_KIND_EXTRA: dict[str, list[str]] = {
    "explosion": ["from the bang", "by the bang", "in the bang", "cooking off", "rounds cooking off"],
    # (stop 37's words, kept out of the kinds' votes: a word added to DANGER_KINDS moves a whole kind in some KB)
    "chemical": ["leakin oil", "leakin fuel", "leakin diesel", "the oil on it", "hydraulic oil", "hydraulic fluid", "leaking oil",
                 "oil leak", "black with oil", "thick with oil", "oil pouring out", "crude pouring out", "crude everywhere",
                 "crude all over", "crude on the ground", "crude spilling"],
    "breakage": ["lost windows", "lost its windows", "lost their windows", "lost all its windows", "broken down", "broke down", "has broken down", "has broke down", "s broken down", "s broke down",
                 "has jammed", "s jammed", "seized up", "has seized",
                 "pipe is broken", "pipe's broken", "pipes are broken", "pipe has broken", "pipe is snapped",
                 "pipe's snapped", "is snapped", "s snapped", "lost its last two spans", "lost two spans", "lost a span",
                 "lost its spans", "lost two of its spans", "been ripped out", "ripped out", "hole right through it", "hole right through", "punched a hole in", "punched a hole through", "hole punched", "punched right through", "punched through"],  # "a hole punched right through the wall"
    # (the surge's damage to moorings: "the diesel jetty has broken loose", "pontoons torn off their piles")
    "storm": ["tumbling round", "tumbling around", "tumbling across", "cartwheeling", "flying gazebo", "roof is half off", "roof's half off", "roof half off", "roof is like half off", "roof's like half off",
              "wedged across it", "wedged across the",
              "come clean off", "came clean off", "lightning strike", "took a lightning strike", "struck by lightning", "hit by lightning", "lightning struck",
              "lightning's struck", "lightning has struck", "lightning hit", "lightning's hit", "lightning has hit",
              "blown over", "been blown over", "has blown over", "torn off their piles", "torn off its piles", "off their piles", "off its piles", "broken loose",
              "broke loose", "torn loose", "all fell over in the wind", "fell over in the wind", "blew over in the wind",
              "poles are fallen", "poles have fallen", "poles have come down", "wind has broken", "wind's broken",
              "tearing loose", "ripping loose", "coming loose", "come loose", "came loose", "has broken free", "come adrift", "broken adrift", "torn from its moorings",
              "is adrift", "s adrift", "gone adrift", "drifting free", "broken every mooring", "broken all her moorings",
              "broken her moorings", "broken its moorings", "broke her moorings", "broke its moorings", "broken their moorings", "broke their moorings",
              "parted her moorings", "parted its moorings", "torn up", "been torn up", "planks are all up",
              "planks are up", "planking is up", "planking's up",
              "windows all blown out", "windows blown out", "windows are blown out", "windows have blown out", "all blown out", "strewn across", "strewn over", "strewn all over", "on their sides", "on its side", "onto its side", "onto their sides", "blew in", "blew straight in", "blown straight in", "roof is gone", "roof's torn", "torn clean off", "came down through", "peeled off", "been peeled off", "peeled back", "lost its roof", "lost their roof", "lost their roofs",
              "lost the roof", "lost its leads", "lost the leads", "roof lifted", "blown clean off", "blown off",
              "off its hinges", "pulled up by the roots", "open to the sky", "rain's coming in", "rain is coming in",
              "rain coming straight in", "rain's coming straight in", "rain pouring in", "rain is pouring"],
    "fire": ["catching embers", "are catching embers", "taking embers", "embers are coming down", "embers coming down", "embers falling", "embers raining down", "embers are raining down", "embers landing", "haven't caught", "hasn't caught", "havent caught", "hasnt caught", "it's scalding", "it is scalding", "scalding hot", "water is boiling", "water's boiling now", "boiling hot",
             "starting to burn", "started to burn", "begun to burn", "beginning to burn", "taken hold of", "has taken hold", "taken hold in", "took hold of", "taking hold of", "flare-up", "flare up", "flared up", "flaring up", "burning debris", "roof is going up", "houses have caught", "have caught", "is going up", "s going up", "going up properly", "roof's going up", "roofs going up", "thatch is going up", "thatch's going up",
             "thatch going up", "embers are landing", "embers landing", "embers are falling", "embers falling", "embers coming down"],
    "electric": ["wire is hot", "wires are hot", "line is hot", "lines are hot", "wire as hot", "wires as hot",
                 "conductors are on", "conductor down", "conductors down", "feeder is down", "feeder down", "lines down",
                 "line down", "lines are down", "line is down", "wires down", "wire down", "wires are down",
                 "cables down", "cable down", "cables are down", "transformer's blown", "transformer has blown",
                 "transformer blew", "transformer's gone bang"],
    "gas": ["smell like bleach", "smells like bleach", "smell of bleach", "smells of bleach", "stink of bleach",
            "the cloud's now", "the cloud is now", "cloud's got into", "cloud has got into", "cloud's drifting",
            "cloud is drifting", "cloud's moving", "cloud is moving", "gassing off", "gassing out", "is gassing", "s gassing", "rotten egg", "rotten eggs", "rotten-egg smell", "rotten egg smell", "eggy smell", "smell like eggs", "smells like eggs", "smell of eggs", "smells of eggs", "smell like rotten eggs", "stinks of eggs", "stinks of rotten eggs", "stink of eggs", "reeks of eggs", "reeks of rotten eggs", "smell of rotten eggs", "smells of rotten eggs", "like egg", "like eggs", "like rotten egg", "there's a hiss", "a loud hiss", "hissing out of", "h2s", "so2", "co2", "sulphur dioxide", "hydrogen sulphide", "carbon dioxide", "methane", "methane leak", "natural gas", "co detected", "co reading", "co readings", "co levels", "high co", "carbon monoxide", "carbon monoxide alarm", "co alarm"],
    "collapse": ["that's broke up", "thats broke up", "is broke up", "has broke up", "s broke up", "broken up", "has broken up", "it's all rotten", "it's rotten", "ice is rotten", "ice s rotten", "rotten right across", "the fallen roof of", "fallen roof of", "whole house just dropped", "house just dropped", "whole house dropped", "slab come off", "slab came off", "slab has come off", "slab's come off", "a big hole in", "big hole in the", "huge hole in the", "a hole in the ground", "hole in the crust",
                 "started to sag", "starting to sag", "begun to sag", "beginning to sag", "wall's come in", "wall has come in", "walls have come in", "wall's come down on", "roof's come in",
                 "roof has come in", "ceiling's come in", "ceiling has come in", "tipped over", "has tipped over", "have tipped over", "have slid", "has slid",
                 "flattened", "been flattened", "torn to bits", "torn to pieces", "ripped to bits", "ripped to pieces", "blown to bits", "giving way", "is giving way", "gives way", "piles are sheared", "piles have sheared", "pile is sheared", "pile's sheared", "torn open", "been torn open", "gone over into the water", "gone over into the lagoon", "gone over into the sea", "gone over into the river", "split down a seam", "split a seam", "split its seam", "split at the seam", "split along a seam", "has snapped", "have snapped", "cable snapped", "cables snapped", "hanging sideways", "floor went through", "floor went thru", "floor gone through", "developed a lean", "has a lean", "bricks coming off", "bricks are coming off", "wall has split", "walls have split", "has split from", "split right across", "split from top to bottom", "roof's coming in", "roof is coming in", "ceiling's coming in", "ceiling is coming in", "coming off in chunks", "coming away in chunks", "falling off in chunks", "in chunks", "breaking up", "is breaking up", "coming adrift", "come adrift", "broken adrift", "peeling off", "coming off in slabs", "coming away in slabs", "roof fall on", "roof fall in", "roof has dropped", "pole's snapped", "pole has snapped", "poles have snapped", "poles snapped", "canvas is down", "canvas's down", "canvas has come down", "canvas came down", "tent's down", "tent is down", "poles down", "poles are down", "roof's dropped", "roof dropped", "ceiling has dropped", "ceiling's dropped", "roof has split", "roof split", "is bending", "it's bending", "is fall down", "has fall down", "fallen down"],
    "water": ["flood tide", "under a flood tide", "flood tide is over", "flood tide's over", "tide is over", "tide's over",
              "tide is coming over", "tide's coming over", "water's worst", "water is worst", "water's at its worst", "water's deepest", "water is deepest", "in spate", "in full spate", "jellyfish", "jellyfish bloom", "jellies everywhere", "stingers everywhere", "running bank to bank", "bank to bank", "going down by the bow", "going down by the stern", "down by the bow", "down by the stern",
              "down by the head", "waves coming straight over", "waves coming right over", "roof is leaking", "roof's leaking",
              "roof leaking", "roof leaks", "taken the surge", "took the surge", "drums floating", "floating everywhere",
              "taken in loads of water", "taken in water", "taken in a lot of water", "taking in loads of water",
              "a metre in there", "a foot in there", "that's going over", "that is going over", "over the tops of their walls", "over the top of their walls", "over the top of its walls", "over the tops of its walls", "over the top of the walls", "gone over their walls", "gone over its walls", "over their walls", "lifting off their stands", "lifted off their stands", "off their stands", "floating off", "floated off",
              "getting swamped", "cars are floating", "cars are floating in it", "tents are floating", "standing in water", "stood in water", "standing in floodwater", "water through all the", "water through the front door", "water through the front doors", "water through the doors", "boiling over", "boiled over", "water is running across", "water running across", "water is lapping", "water lapping", "lapping the", "over the towpath", "across the towpath", "gates burst", "gates have burst", "gate burst", "gate has burst", "pouring over", "topped its bank", "topped its banks", "topped the bank", "topped the banks", "gone over the bank", "gone over its bank", "gone over the south bank", "gone over the north bank", "gone over the east bank", "gone over the west bank", "metre deep", "metres deep", "meter deep", "a metre of water", "under a metre of", "under half a metre of", "under half a metre", "under half a meter", "under a foot of", "under two foot of", "under three foot of", "under two feet of", "under three feet of", "water's going right over", "water is going right over", "water's going over the deck", "going right over the deck", "over the deck", "up to the doors", "up to the front doors", "up to the stable doors", "metre of water", "full to the top", "full to the brim", "water all the way round", "water is all the way round", "water all round", "water is all round", "water right round", "water is right round", "tide's coming straight through", "tide's coming through", "tide coming through", "sea's coming through", "one sheet of water", "a sheet of water", "sheet of water", "washing out", "washing away", "logs floating", "floating away", "floating off the floor", "floating about", "floating around",
              "furniture floating", "chairs floating", "cars floating",
              "water coming through", "water's coming through", "water is coming through", "seeping through the walls",
              "water at the front door", "water at the door", "water's at the door", "water's at the front door",
              "water at the windows", "water's at the windows", "water is at the windows", "water's right round",
              "water right round", "water all round", "water's all round", "water all around", "water's all around",
              "yard's a lake", "is a lake", "'s a lake", "like a lake", "completely under", "cut off by water", "cut off by the water", "cut off by floodwater", "cut off by the flood", "over its banks", "over the banks", "out of its banks", "broken its banks", "burst their banks", "bursting its banks", "scoured", "scoured out", "water coming through the ceiling", "water through the ceiling", "water pouring through the ceiling",
              "water coming through the roof", "ceiling's leaking", "ceiling is leaking", "water pouring through", "bricks pouring off", "bricks pouring down", "masonry pouring off", "spurting through", "spurting out", "water spurting", "jetting out", "water jetting",
              "drowned out", "foot under", "feet under", "metre under", "metres under", "inches under",
              "water's at the top of", "water is at the top of",
              "water at the top of", "water's up to the top of", "water is up to the top of"],
    "access": ["jammed", "jammed solid", "blocking", "blocking the way", "blocking it", "blocks the way", "rocks across", "rocks across it", "rocks across the road", "debris across", "debris right across", "fallen oak", "fallen beech", "fallen ash", "fallen branch", "fallen branches"],
    "ground": ["dead slippery", "really slippery", "covered in weed", "spoil's already through", "spoil is already through", "spoil's through", "spoil is through", "spoil's come through",
               "spoil has come through", "spoil's come down", "spoil has come down", "strewn with rocks", "strewn with boulders", "littered with rocks", "littered with boulders", "buried to the axles", "buried to its axles", "buried up to the axles", "buried up to its axles",
               "sunk to the axles", "sunk to its axles", "bogged down", "there's a slip on", "there's been a slip on", "there is a slip on", "scree moving", "scree is moving", "ground is moving", "ground moving", "slope is moving", "hillside is moving", "rocks are coming off", "rocks are coming down", "rocks are falling", "dropping rocks", "rocks dropping", "dropping stones", "has sunk", "have sunk", "its sunk", "ground dropped", "ground has dropped", "ground dropping", "ground is dropping", "ground gone", "ground has gone", "ground just gone", "floor dropped", "floor has dropped", "hole opened up", "hole has opened up", "hole just opened up", "floor has opened", "floor's opened", "sinkhole", "sink hole", "ash a foot deep", "ash is knee deep", "ash knee deep", "ash's knee deep", "ash is ankle deep", "a foot of ash", "feet of ash", "inches of ash", "deep in ash", "covered in ash", "ash everywhere", "covered in stones", "covered in rocks", "covered in boulders", "covered with stones", "covered with rocks", "stones all over it", "rocks all over it", "heaped with ash", "buried in ash", "under the ash", "drifts of ash", "ash drifts", "half buried", "half-buried", "slurry", "full of slurry", "sludge", "silt", "full of silt"],
    "fallen": ["tree's down", "tree is down", "tree down", "trees are down", "trees down", "tree's come over",
               "tree has come over", "come over in the wind", "came over in the wind", "taken the top off", "took the top off", "knocked the top off", "blown the top off", "blew the top off",
               "stonework through", "masonry through", "through the glass roof", "debris through the roof",
               "rubble through the roof", "branch through the roof", "branch through its roof", "branches through the roof", "limb through the roof",
               "tree through its roof", "trees through the roof", "hole in the roof", "holes in the roof", "hole in its roof", "hole in the wall", "lost a parapet", "lost its parapet", "lost the parapet", "lost a wall", "lost its wall", "lost a gable", "lost its gable",
               # ("a tree's come straight through our roof", "a tree through the arbour", "lost three trees")
               "tree through", "trees through", "through our roof", "come through the roof", "come straight through the roof",
               "lost a tree", "lost two trees", "lost three trees", "lost four trees", "lost some trees", "lost several trees",
               "lost trees", "lost a few trees", "taken a hit", "took a hit", "taking a hit"],
}

for _phrases in DANGER_KIND_EXTRA.values():  # each an undesirable cue as well, as the kinds' own phrases are
    for _p in _phrases:
        ROLE_CUES.setdefault(_p, UNDESIRABLE)
# bees or wasps swarming at a place ("swarm at the beehives")
for _p in ("swarm", "swarming", "bees swarming", "angry bees", "wasps swarming"):
    ROLE_CUES.setdefault(_p, UNDESIRABLE)

# Nouns for the way to a place, between a relation and its anchor ("guarding the way into reception")
APPROACH_NOUNS = _keyed({"way", "approach", "approaches", "entrance", "road", "path", "route", "gate", "door"})

# Dangers said in the plural that "they're out" can put out ("flames at the bakery but they're out now")
PLURAL_FIRES = frozenset({"flames", "flame", "fires", "fire"})

# Place nouns of three letters that may stand for a name they end ("the gym" for "hollis school gym")
# Units a depth or a length is measured in ("in a foot of it", "two metres of water")
MEASURE_UNITS = frozenset({"foot", "feet", "metre", "metres", "meter", "meters", "inch", "inches", "mile", "miles"})
# (not "yard": "the place that shares a yard with the hut")
# Prepositions of place that PREPOSITIONS leaves out ("the heap above the pit the slurry pond spills into")
PLACE_PREPOSITIONS = frozenset({"above", "below", "beneath", "underneath", "beyond", "opposite", "onto", "off"})
# Words of danger too short for the four-letter floor on the words that match a phrase to a category description,
# that still name its kind ("leaking gas": "gas leaks and breakouts", not "leaking lagoons")
SHORT_DANGER_WORDS = frozenset({"gas", "oil", "mud", "ice", "ash", "fog"})
# Words of danger that name no kind of it ("it's getting dangerous")
GENERIC_DANGER_WORDS = frozenset({"danger", "dangerous", "dangerously", "unsafe", "hazard", "hazardous", "hazards",
                                  "threat", "risk", "risky", "getting"})
# Animals, where a KB gives them a category of their own ("bullocks stuck in the cattle lines")
ANIMAL_WORDS = _keyed({"bird", "birds", "sheep", "ewe", "ewes", "lamb", "lambs", "tup", "tups", "ram", "rams", "cow", "cows", "cattle", "bullock", "bullocks", "heifer", "heifers", "calf", "calves", "bull", "bulls", "steer", "steers", "beast", "beasts", "stock", "livestock", "horse", "horses", "pony", "ponies", "foal", "pig", "pigs", "sow", "sows", "goat", "goats", "dog", "dogs", "animal", "animals", "hens", "chickens", "elephant", "elephants", "lion", "lions", "tiger", "tigers", "cats", "camel",
                          "camels", "donkey", "donkeys", "llama", "llamas", "alpaca", "alpacas", "mare", "mares",
                          "stallion", "stallions", "geese", "lioness", "lionesses", "zebra", "zebras", "giraffe",
                          "giraffes", "rhino", "rhinos", "hippo", "hippos", "baboon", "baboons", "monkey", "monkeys",
                          "ostrich", "ostriches", "wolf", "wolves", "bear", "bears", "deer", "bison", "buffalo",
                          "antelope", "antelopes", "cheetah", "cheetahs", "leopard", "leopards", "gibbon", "gibbons",
                          "nanny", "nannies", "billies", "reindeer", "herd", "mule", "mules", "ox", "oxen", "yak",
                          "yaks", "ducks", "turkeys", "poultry"})
# Injuries said of a body part ("burns to the face", "a cut on the head")
INJURY_WORDS = frozenset({"burns", "burn", "burned", "burnt", "cut", "cuts", "injury", "injuries", "wound", "wounds",
                          "hit", "struck", "blow", "bleeding", "lacerations", "laceration", "scalds", "scalded", "gash",
                          "bruising", "bruised", "bump", "knock"})
# States only animals in trouble are said to be in, read of a clause's animal subject ("the bulls ... are going
# frantic"), where a KB has a category for animals
ANIMAL_STATES = ("panicking", "frantic", "bolting", "bolted", "stampeding", "spooked", "screaming", "trumpeting",
                 "rearing", "going frantic", "going mental", "going berserk", "kicking off", "loose", "escaped",
                 "got out", "roaming", "wandering about", "wandering around", "running loose", "are through",
                 "got through", "broken through", "broke through", "is through", "is out", "are out", "s out", "still out", "got into", "run into", "ran into")
# What animals in trouble are said to be ("a bullock loose", "ewes swimming"), for a KB with a category for them
ANIMAL_TROUBLE = ("loose", "on the loose", "got loose", "got out", "escaped", "swimming", "stranded", "trapped", "stuck",
                  "down", "cast", "in the water", "washed away", "drowning", "panicking", "bolting", "bolted", "stampeding",
                  "going mental", "going frantic", "frantic", "screaming", "spooked", "kicking off", "going berserk")
# Verbs of bringing people ("anyone you bring up from the river end": where they come from, no claim)
BRING_VERBS = frozenset({"bring", "brought", "bringing", "fetch", "fetched", "fetching", "carry", "carried", "carrying"})
# What a crew does to a place ("we've shut the gallopers down"): said of the place, it claims nothing of it
CREW_ACTION_VERBS = frozenset({"shut", "closed", "evacuated", "emptied", "cleared", "cordoned", "taped", "sealed",
                               "locked", "stopped", "searched", "checked", "swept"})
# Verbs of people moving away that take "clear" ("crew have stepped well clear"): no safe place said
MOVED_CLEAR_VERBS = frozenset({"stepped", "stood", "backed", "moved", "pulled", "jumped", "scrambled",
                               "step", "stand", "move", "pull", "standing", "stepping", "backing"})
SHORT_PLACE_NOUNS = frozenset({"gym", "pub", "inn", "spa", "zoo", "dam", "tip"})
# Words for parts of a building that MiniLM's vocabulary lacks: English words, no typed slips of a name ("panes
# cracked overhead" is no slip of "the panels")
BUILDING_PART_WORDS = _keyed({"pane", "panes", "joist", "joists", "rafter", "rafters", "girder", "girders", "hinge",
                              "hinges", "gutter", "gutters", "flue", "flues", "soffit", "lintel", "strut", "struts",
                              "glazing", "truss", "trusses", "purlin", "purlins"})
# Kinds of place said by another word ("the pub" for a landmark its description calls an inn)
PLACE_KIND_SYNONYMS = {"pub": ("inn", "tavern", "alehouse"), "inn": ("pub", "tavern"), "tavern": ("pub", "inn"),
                       "shop": ("store",), "store": ("shop",)}

# Clipped words that stand for a longer first word of a name ("the bio block", "the sci park"), though they
# are words of their own too
CLIPPINGS = frozenset({"bio", "sci", "tech", "med", "lab", "admin", "chem", "maths", "eng", "vet", "physio"})

# The radio alphabet: "Bravo wing", "on Charlie" for a KB's "b wing" / "c wing".
PHONETIC_LETTERS = {"alpha": "a", "alfa": "a", "bravo": "b", "charlie": "c", "delta": "d", "echo": "e",
                    "foxtrot": "f", "golf": "g", "hotel": "h", "india": "i", "juliet": "j", "juliett": "j",
                    "kilo": "k", "lima": "l", "mike": "m", "november": "n", "oscar": "o", "papa": "p", "quebec": "q",
                    "romeo": "r", "sierra": "s", "tango": "t", "uniform": "u", "victor": "v", "whiskey": "w",
                    "whisky": "w", "xray": "x", "yankee": "y", "zulu": "z"}

# Words that tell two landmarks of a pair apart ("upper car park" / "lower car park"); direction words
# with an antonym count as well.
SIDE_WORDS = frozenset({"north", "south", "east", "west", "northbound", "southbound", "eastbound", "westbound",
                        "upper", "lower", "inner", "outer", "front", "rear", "top", "bottom", "northern", "southern",
                        "eastern", "western", "near", "far", "left", "right", "old", "new"})

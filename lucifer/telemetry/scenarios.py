"""Seeded generator of location signatures for the discovery benchmark and simulated clients.

A *location signature* is a short text description of what a searcher observes at an
information location ("muffled knocking under debris, near the school"). Its correct query
option is the one whose meaning fits it: knocking under debris calls for ``acoustic_listen``.

Phrasings come from three disjoint pools per option:

* ``seen``: used to build telemetry memory and for in-memory decision points;
* ``dev``: the calibration split (fits the confidence temperature); never in memory;
* ``novel``: the held-out test pool; never in memory, never used for fitting.

A signature is one or two cue phrases of its option, optionally followed by a neutral place
context (contexts are split the same way). Randomness comes only from the caller's
:class:`numpy.random.Generator`, so the same seed gives the same signatures.

>>> import numpy as np
>>> a = sample_signature("gas_sniffer", np.random.default_rng(3))
>>> a == sample_signature("gas_sniffer", np.random.default_rng(3))
True
>>> sorted(set(QUERY_INFO_TYPE.values()))
['hazard', 'safe_route', 'victim']
"""

from __future__ import annotations

from typing import Literal

import numpy as np

Pool = Literal["seen", "dev", "novel"]
POOLS: tuple[Pool, ...] = ("seen", "dev", "novel")

#: option name -> the mission information type its answer reveals
QUERY_INFO_TYPE: dict[str, str] = {
    "thermal_scan": "victim",
    "acoustic_listen": "victim",
    "ask_bystanders": "victim",
    "search_dog": "victim",
    "check_radio_log": "victim",
    "structural_inspection": "hazard",
    "gas_sniffer": "hazard",
    "electrical_check": "hazard",
    "hazmat_test": "hazard",
    "flood_gauge": "hazard",
    "drone_overflight": "safe_route",
    "check_building_plans": "safe_route",
    "scout_route": "safe_route",
    "check_traffic_cameras": "safe_route",
    "measure_clearance": "safe_route",
}

#: the query options, in the order of ``knowledge_base/query_options.yaml``
OPTIONS: tuple[str, ...] = tuple(QUERY_INFO_TYPE)

_CUES: dict[str, dict[Pool, tuple[str, ...]]] = {
    "thermal_scan": {
        "seen": (
            "thick smoke, nothing visible inside",
            "pitch dark basement, someone may be inside",
            "warm patch on the collapsed roof",
            "dense smoke filling the hallway",
            "blacked-out room with no lights",
            "possible person hidden in the dark",
            "heat shimmer above the debris",
            "night time, no visibility",
            "smoke-filled stairwell",
            "figure glimpsed then lost in the smoke",
        ),
        "dev": (
            "an attic nobody can see into, maybe a child up there",
            "clouds of soot hiding whoever is inside",
            "a faint warm outline behind the plasterboard",
            "blackout in the cinema, people may still be seated",
            "the boiler room is murky and someone might be lying there",
        ),
        "novel": (
            "black smoke pouring out, could be people inside",
            "lightless crawlspace that might hold a survivor",
            "something warm under the fallen timbers",
            "haze so thick you cannot see your hand",
            "darkened ward with no power, patients unaccounted",
            "smouldering room, occupants unknown",
        ),
    },
    "acoustic_listen": {
        "seen": (
            "muffled knocking under debris",
            "tapping on a pipe below the slab",
            "faint voice from under the rubble",
            "collapsed stairwell, sounds from below",
            "banging heard beneath the floor",
            "someone groaning under the concrete",
            "rhythmic tapping from the wreckage",
            "weak cries under the collapsed roof",
            "scratching noises beneath the pile",
            "a phone ringing under the debris",
        ),
        "dev": (
            "a muffled cough comes from beneath the slabs",
            "somebody keeps banging a spoon under the collapsed kitchen",
            "faint humming from inside the fallen shaft",
            "thuds answering our shouts from below ground",
            "a weak whistle from somewhere under the beams",
        ),
        "novel": (
            "faint calls for help buried somewhere below",
            "rapping on metal under the heap of bricks",
            "whimpering from inside the pancaked floors",
            "a buried alarm clock still beeping",
            "muted shouting beneath the wreck",
            "someone hitting a pipe down in the void",
        ),
    },
    "ask_bystanders": {
        "seen": (
            "crowd of neighbours gathered outside",
            "witnesses say someone went back in",
            "a woman says her son is missing",
            "shop owner unsure if staff got out",
            "residents arguing about who is unaccounted for",
            "people outside pointing at a window",
            "neighbour claims an elderly man lives upstairs",
            "onlookers saw someone run inside",
            "family waiting at the cordon",
            "passer-by reports hearing screams earlier",
        ),
        "dev": (
            "an elderly neighbour insists the couple upstairs never left",
            "the caretaker is listing who signed in today",
            "a girl says her grandmother was in the back room",
            "the cafe owner counts staff and one is missing",
            "a crowd at the barrier is shouting names",
        ),
        "novel": (
            "a tearful father asking about his daughter",
            "the landlady thinks two lodgers were home",
            "children outside say their friend is still in there",
            "a delivery driver saw someone enter before the collapse",
            "a cluster of residents comparing who they have seen",
            "a shopkeeper mentions a customer never came out",
        ),
    },
    "search_dog": {
        "seen": (
            "huge rubble field, no sounds at all",
            "silent debris pile across the whole block",
            "large collapse, location of occupants unknown",
            "wide area of wreckage, nobody responding",
            "multiple buildings down, no signs of life heard",
            "vast heap of bricks, silent",
            "debris spread over a wide area",
            "collapsed warehouse, no response to calls",
            "scattered rubble everywhere, quiet",
            "pile too big to search by hand",
        ),
        "dev": (
            "a quarry of broken concrete where the flats used to be, nobody answers",
            "an enormous spill of bricks and no idea where anyone is",
            "the collapse covers half the block and it is dead quiet",
            "a vast tangle of wreckage, calls go unanswered",
            "the market hall is flattened and silent throughout",
        ),
        "novel": (
            "an entire row of homes reduced to rubble and utterly quiet",
            "acres of wreckage with no reply to shouting",
            "the whole terrace came down, not a sound",
            "mountain of masonry with no clue where people are",
            "sprawling ruins without any signal of survivors",
            "a flattened apartment block, eerily silent",
        ),
    },
    "check_radio_log": {
        "seen": (
            "team member stopped answering the radio here",
            "last known position of a missing firefighter",
            "an emergency call came from this address earlier",
            "dispatch logged a mayday nearby",
            "earlier radio message mentioned this building",
            "a crew checked in here then went silent",
            "caller reported being trapped here before the line cut",
            "lost contact with the search team at this spot",
            "dispatcher mentions repeated calls from here",
            "unit's last check-in was at this corner",
        ),
        "dev": (
            "the patrol's radio has been silent since they entered here",
            "base logged a cry for help from this flat before the line dropped",
            "a paramedic's tracker last reported from this spot",
            "the night shift recorded a call mentioning this yard",
            "someone radioed they were pinned here, then nothing",
        ),
        "novel": (
            "the control room recorded a distress message from this street",
            "a volunteer's handset went dead at this point",
            "an operator took a call from someone stuck here an hour ago",
            "the last ping from the rescue team came from here",
            "command noted a garbled transmission about this block",
            "the logbook shows a caller at this address",
        ),
    },
    "structural_inspection": {
        "seen": (
            "large cracks running up the wall",
            "leaning facade over the entrance",
            "sagging ceiling beams",
            "floor bowing under weight",
            "chunks of plaster falling",
            "doorframe twisted out of shape",
            "balcony hanging loose",
            "wall bulging outward",
            "roof partially caved in",
            "staircase pulling away from the wall",
        ),
        "dev": (
            "the chimney stack has shifted and the roof is bowed",
            "a supporting pillar is cracked right through",
            "the party wall is peeling away from the house",
            "the mezzanine floor is visibly slumped",
            "the gable end is bulging out over the path",
        ),
        "novel": (
            "the whole frontage is leaning toward the street",
            "fractures zig-zagging across the brickwork",
            "the upper storey looks ready to drop",
            "a column has buckled in the lobby",
            "ceiling drooping in the middle of the room",
            "gaps opening between the walls and floor",
        ),
    },
    "gas_sniffer": {
        "seen": (
            "strong smell of gas",
            "hissing from a broken pipe",
            "rotten egg odour near the meter",
            "gas meter knocked off the wall",
            "fumes near the boiler room",
            "dizzy feeling near the kitchen stove",
            "bubbling in a puddle over the gas main",
            "broken gas line at the corner",
            "propane tanks toppled over",
            "smell like sulphur in the air",
        ),
        "dev": (
            "a strong whiff of mercaptan near the boiler",
            "a line from the cooker has come loose and is hissing",
            "the pilot lights are out and the air smells foul",
            "LPG bottles are lying on their side in the yard",
            "a leaking regulator on the heater",
        ),
        "novel": (
            "a whistling leak from the supply line",
            "people complaining of headaches near the cooker",
            "odour of rotten eggs drifting from the cellar",
            "the mains valve is sheared off",
            "gas canisters rolled into the rubble",
            "a faint sulphurous stink by the heating unit",
        ),
    },
    "electrical_check": {
        "seen": (
            "power line down across the road",
            "sparks from a hanging cable",
            "buzzing transformer",
            "exposed wires in the water",
            "electrical panel smoking",
            "lights flickering in the flooded basement",
            "cable dangling over the doorway",
            "crackling from the fuse box",
            "street lamp pole fallen with wires",
            "arcing from a broken socket",
        ),
        "dev": (
            "an overhead cable has fallen into the puddles",
            "the substation fence is buzzing loudly",
            "sparks spitting from the shopfront sign",
            "the consumer unit is charred and still live",
            "wires hanging into the flooded stairwell",
        ),
        "novel": (
            "a snapped utility cable twitching on the pavement",
            "blue flashes from the junction box",
            "the meter cupboard is crackling",
            "a toppled pylon with lines draped over cars",
            "water pooling around an outlet that still has power",
            "loud electrical hum from the basement",
        ),
    },
    "hazmat_test": {
        "seen": (
            "leaking drums of unknown liquid",
            "strange coloured puddle spreading",
            "chemical smell from the storage room",
            "broken containers with warning labels",
            "stinging eyes near the warehouse",
            "white powder spilled on the floor",
            "pool of oily liquid with fumes",
            "pharmacy storeroom shelves toppled, bottles smashed",
            "corrosive label on a cracked tank",
            "foam oozing from a barrel",
        ),
        "dev": (
            "a tanker has spilled something orange across the road",
            "bleach and ammonia bottles broken together in the cupboard",
            "sacks of pesticide ripped open in the shed",
            "eyes watering near the dry cleaner's vats",
            "an unlabelled drum oozing a thick syrup",
        ),
        "novel": (
            "canisters marked with skull symbols split open",
            "a pungent solvent stench from the workshop",
            "fertiliser sacks burst and soaked",
            "throat burning near the cleaning supplies",
            "a rainbow sheen spreading across the yard",
            "glass jars of reagents shattered across the bench",
        ),
    },
    "flood_gauge": {
        "seen": (
            "water rising in the basement",
            "street flooded to knee height",
            "fast current through the underpass",
            "burst water main gushing",
            "cellar filling with water",
            "river overflowing near the bridge",
            "muddy water up to the doorsteps",
            "sewer overflowing",
            "ground floor under water",
            "water pouring down the stairs",
        ),
        "dev": (
            "the brook has risen over the footbridge",
            "the basement car park is filling with brown water",
            "water surging out of the storm drains",
            "the cellar steps have disappeared under water",
            "the square is ankle deep and still rising",
        ),
        "novel": (
            "the lane has turned into a stream",
            "brown floodwater creeping higher by the minute",
            "the subway entrance is submerged",
            "a torrent rushing through the car park",
            "water lapping at the window sills",
            "the canal has breached its bank",
        ),
    },
    "drone_overflight": {
        "seen": (
            "no view past the collapsed buildings",
            "cannot see which streets are blocked",
            "roof access only, nothing visible from the ground",
            "wide area, road status unknown",
            "blocked view of the streets ahead",
            "need an overview of the whole district",
            "unclear which route around the block is open",
            "debris on rooftops, cannot reach",
            "route beyond the rubble unknown",
            "far end of the avenue not visible",
        ),
        "dev": (
            "we cannot tell which way around the district is open",
            "the skyline is too cluttered to judge the roads beyond",
            "no ground view of the far streets past the collapse",
            "the flat roofs across the estate need checking from above",
            "what lies behind the tower block is a mystery",
        ),
        "novel": (
            "nobody knows what lies beyond the collapsed overpass",
            "a bird's-eye picture of the neighbourhood would help",
            "which of the three streets leads out is unclear",
            "the far side of the park is hidden behind wreckage",
            "roof terraces that ground teams cannot check",
            "the whole quarter's layout changed after the quake",
        ),
    },
    "check_building_plans": {
        "seen": (
            "unfamiliar building layout",
            "looking for a second exit",
            "where does the back corridor lead",
            "basement access unknown",
            "maze of corridors inside",
            "need the stairwell locations",
            "fire escape location unknown",
            "large hospital wing with many rooms",
            "hidden service tunnel rumoured",
            "which door leads to the courtyard",
        ),
        "dev": (
            "the department store has stairs nobody can find",
            "is there a loading bay door at the rear",
            "the hospital annex corridors are a labyrinth",
            "where the boiler room entrance is remains unclear",
            "which stairwell reaches the roof is unknown",
        ),
        "novel": (
            "the interior is a warren of rooms nobody has mapped",
            "is there a rear staircase to the upper floors",
            "an underground passage may link the two buildings",
            "the emergency exits are not signposted",
            "the school's wings connect in some unclear way",
            "nobody remembers where the cellar door is",
        ),
    },
    "scout_route": {
        "seen": (
            "narrow alley partly blocked",
            "footpath with some debris",
            "side passage might be open",
            "shortcut through the courtyard",
            "lane with a fallen tree",
            "path behind the shops uncertain",
            "walkway partly covered in glass",
            "gap between two cars on the road",
            "stepping stones of rubble across the lane",
            "garden gate route to the next street",
        ),
        "dev": (
            "a gap between the hedges might lead through",
            "the back lane might still be walkable",
            "a muddy track behind the allotment sheds",
            "the underpass footway, partly blocked by bins",
            "a little passage past the church may be clear",
        ),
        "novel": (
            "a cramped passage between the houses, maybe walkable",
            "the cut-through behind the market could still be open",
            "a cycle path littered with branches",
            "the towpath looks damp but maybe usable",
            "a snicket strewn with broken tiles",
            "a route over the low garden walls",
        ),
    },
    "check_traffic_cameras": {
        "seen": (
            "intersection jammed with cars",
            "abandoned vehicles on the main road",
            "traffic backed up at the junction",
            "camera on the corner pole",
            "roundabout status unknown",
            "gridlock reported downtown",
            "crashed bus blocking the junction",
            "traffic lights out at the crossroads",
            "convoy stuck somewhere on the avenue",
            "cars left with doors open on the street",
        ),
        "dev": (
            "the high road junction is packed with stopped vans",
            "buses abandoned across the lanes",
            "no idea whether the bypass is flowing",
            "a truck overturned at the lights",
            "drivers fled and left their cars at the crossing",
        ),
        "novel": (
            "vehicles deserted all along the high street",
            "a lorry jackknifed across the crossing",
            "nobody can say if the ring road is moving",
            "tailbacks rumoured near the bridge approach",
            "the signals are dead and cars are tangled at the junction",
            "evacuating motorists clogging the boulevard",
        ),
    },
    "measure_clearance": {
        "seen": (
            "low hanging beam over the passage",
            "gap between fallen slabs",
            "narrow opening in the debris",
            "doorway half blocked, width unclear",
            "will the ambulance fit under the sign",
            "tight squeeze between collapsed walls",
            "opening maybe too small for a stretcher",
            "height under the fallen girder",
            "vehicle clearance under the tilted lamp post",
            "gap in the fence for the truck",
        ),
        "dev": (
            "can the rescue van squeeze past the toppled billboard",
            "the hole in the rubble looks narrow for a stretcher",
            "a fallen girder leaves a low gap above the road",
            "the gateway is half blocked, is it wide enough",
            "the tunnel mouth is partly choked, height unknown",
        ),
        "novel": (
            "a slot between two concrete slabs, maybe wide enough to crawl",
            "the fire engine might not pass beneath the bent gantry",
            "how wide is the hole punched through the wall",
            "a crawl space whose height nobody knows",
            "a partly jammed garage door, possibly enough room for a gurney",
            "an archway choked with debris, width uncertain",
        ),
    },
}

_CONTEXTS: dict[Pool, tuple[str, ...]] = {
    "seen": (
        "north side of the square",
        "by the bakery",
        "behind the church",
        "on the main road",
        "near the school",
        "at the corner shop",
        "next to the bank",
        "outside the pharmacy",
        "by the old mill",
        "across from the library",
    ),
    "dev": (
        "near the post office",
        "by the town hall",
        "on the west road",
        "behind the hotel",
    ),
    "novel": (
        "down by the docks",
        "off the ring road",
        "at the far end of the estate",
        "beside the allotments",
        "past the cemetery gates",
        "under the railway arch",
    ),
}


def cue_phrases(option_name: str, pool: Pool = "seen") -> tuple[str, ...]:
    """The cue phrases of one option in one pool.

    >>> cue_phrases("acoustic_listen")[0]
    'muffled knocking under debris'
    """
    try:
        return _CUES[option_name][pool]
    except KeyError:
        raise KeyError(f"no phrasings for option {option_name!r} in pool {pool!r}") from None


def sample_signature(
    option_name: str,
    rng: np.random.Generator,
    novel: bool = False,
    *,
    pool: Pool | None = None,
) -> str:
    """A location signature whose correct query is ``option_name``.

    ``novel=True`` draws from the held-out phrasing pool that memory and training never use;
    ``pool`` (``seen`` | ``dev`` | ``novel``) overrides it when given.
    """
    chosen: Pool = pool if pool is not None else ("novel" if novel else "seen")
    cues = cue_phrases(option_name, chosen)
    n_cues = 2 if rng.random() < 0.6 else 1
    picks = rng.choice(len(cues), size=n_cues, replace=False)
    text = ", ".join(cues[int(i)] for i in picks)
    if rng.random() < 0.6:
        contexts = _CONTEXTS[chosen]
        text += ", " + contexts[int(rng.integers(len(contexts)))]
    return text


def sample_candidates(
    option_name: str,
    rng: np.random.Generator,
    options: tuple[str, ...] = OPTIONS,
    *,
    low: int = 3,
    high: int = 6,
) -> list[str]:
    """A candidate set U(x_t): the correct option plus ``low..high-1`` distractors, shuffled."""
    others = [o for o in options if o != option_name]
    k = int(rng.integers(low, high))
    picked = [others[int(i)] for i in rng.choice(len(others), size=min(k, len(others)), replace=False)]
    out = [option_name, *picked]
    rng.shuffle(out)
    return out


def all_phrases(pool: Pool) -> set[str]:
    """Every cue and context phrase of a pool (tests check the pools are disjoint)."""
    return {c for per in _CUES.values() for c in per[pool]} | set(_CONTEXTS[pool])

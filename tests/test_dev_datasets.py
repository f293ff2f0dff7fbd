"""The hand-written dev grounding sets (dev2 to dev144) are well-formed and their labels exist in the right KB."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
GROUNDING = ROOT / "datasets" / "grounding"
MARKET_SQUARE = ROOT / "knowledge_base"
RIVERBEND = ROOT / "knowledge_bases" / "riverbend"
HARBOURSIDE = ROOT / "knowledge_bases" / "harbourside"
NORTHGATE = ROOT / "knowledge_bases" / "northgate"
QUARRYTOWN = ROOT / "knowledge_bases" / "quarrytown"
SALTMARSH = ROOT / "knowledge_bases" / "saltmarsh_airfield"
ALPINE = ROOT / "knowledge_bases" / "alpine_village"
PORT = ROOT / "knowledge_bases" / "container_port"
DELTA = ROOT / "knowledge_bases" / "delta_town"
METRO = ROOT / "knowledge_bases" / "metro_interchange"
HILLSIDE = ROOT / "knowledge_bases" / "hillside_quake"
CHEMICAL = ROOT / "knowledge_bases" / "chemical_works"
FESTIVAL = ROOT / "knowledge_bases" / "festival_site"
FERRY = ROOT / "knowledge_bases" / "ferry_ship"
CAMPGROUND = ROOT / "knowledge_bases" / "lakeside_campground"
TUNNEL = ROOT / "knowledge_bases" / "road_tunnel"
STADIUM = ROOT / "knowledge_bases" / "football_stadium"
MALL = ROOT / "knowledge_bases" / "shopping_mall"
HOSPITAL = ROOT / "knowledge_bases" / "hospital_campus"
ZOO = ROOT / "knowledge_bases" / "city_zoo"
PIER = ROOT / "knowledge_bases" / "seaside_pier"
OLD_TOWN = ROOT / "knowledge_bases" / "old_town"
ESTATE = ROOT / "knowledge_bases" / "industrial_estate"
FARM = ROOT / "knowledge_bases" / "farm_village"
CAMPUS = ROOT / "knowledge_bases" / "university_campus"
RAILWAY = ROOT / "knowledge_bases" / "mountain_railway"
CANAL = ROOT / "knowledge_bases" / "canal_wharf"
HOUSING = ROOT / "knowledge_bases" / "housing_estate"
COASTAL = ROOT / "knowledge_bases" / "coastal_village"
RIVER_PORT = ROOT / "knowledge_bases" / "river_port_market"
CATHEDRAL = ROOT / "knowledge_bases" / "cathedral_close"
THEME_PARK = ROOT / "knowledge_bases" / "theme_park"
SERVICES = ROOT / "knowledge_bases" / "motorway_services"
RESERVOIR = ROOT / "knowledge_bases" / "reservoir_valley"
AIRPORT = ROOT / "knowledge_bases" / "airport_terminal"
SKI_TOWN = ROOT / "knowledge_bases" / "ski_town"
SPA_TOWN = ROOT / "knowledge_bases" / "spa_town"
MARKET_TOWN = ROOT / "knowledge_bases" / "market_town"
ISLAND = ROOT / "knowledge_bases" / "island_harbour"
CASTLE_TOWN = ROOT / "knowledge_bases" / "castle_town"
SCIENCE_PARK = ROOT / "knowledge_bases" / "science_park"
RAIL_YARD = ROOT / "knowledge_bases" / "rail_yard"
WINE_ESTATE = ROOT / "knowledge_bases" / "wine_estate"
RACECOURSE = ROOT / "knowledge_bases" / "racecourse"
MINING_TOWN = ROOT / "knowledge_bases" / "mining_town"
TORNADO = ROOT / "knowledge_bases" / "tornado_suburb"
ASH_ISLAND = ROOT / "knowledge_bases" / "ash_island"
TOWER_BLOCK = ROOT / "knowledge_bases" / "tower_block"
REFUGEE_CAMP = ROOT / "knowledge_bases" / "refugee_camp"
HOSPITAL_TOWER = ROOT / "knowledge_bases" / "hospital_tower"
COUNTY_PRISON = ROOT / "knowledge_bases" / "county_prison"
COAST_ROAD = ROOT / "knowledge_bases" / "coast_road"
FOREST_PARK = ROOT / "knowledge_bases" / "forest_park"
DOCKSIDE = ROOT / "knowledge_bases" / "dockside_estate"
HILL_FARM = ROOT / "knowledge_bases" / "hill_farm_show"
DISTILLERY = ROOT / "knowledge_bases" / "distillery_glen"
RETIREMENT = ROOT / "knowledge_bases" / "retirement_village"
FERRY_TOWN = ROOT / "knowledge_bases" / "ferry_terminal_town"
MOORLAND = ROOT / "knowledge_bases" / "moorland_village"
GLASSHOUSE = ROOT / "knowledge_bases" / "glasshouse_suburb"
ESTUARY = ROOT / "knowledge_bases" / "estuary_marina"
GOLF = ROOT / "knowledge_bases" / "golf_resort"
PAPERMILL = ROOT / "knowledge_bases" / "papermill_valley"
CLIFFTOP = ROOT / "knowledge_bases" / "clifftop_park"
TRAMWAY = ROOT / "knowledge_bases" / "tramway_junction"
CIRCUIT = ROOT / "knowledge_bases" / "racing_circuit"
ABBEY = ROOT / "knowledge_bases" / "abbey_village"
WALLED_CITY = ROOT / "knowledge_bases" / "walled_city"
STEELWORKS = ROOT / "knowledge_bases" / "steelworks_town"
TIDAL_ISLE = ROOT / "knowledge_bases" / "tidal_isle"
NEW_TOWN = ROOT / "knowledge_bases" / "new_town"
BRACKENFORD = ROOT / "knowledge_bases" / "brackenford"
THORNWATER = ROOT / "knowledge_bases" / "thornwater"
SHIPYARD = ROOT / "knowledge_bases" / "shipyard_town"
ORCHARD = ROOT / "knowledge_bases" / "orchard_valley"
VIADUCT = ROOT / "knowledge_bases" / "viaduct_town"
POWER_STATION = ROOT / "knowledge_bases" / "power_station"
FEN_TOWN = ROOT / "knowledge_bases" / "fen_town"
BREWERY_TOWN = ROOT / "knowledge_bases" / "brewery_town"
LIGHTHOUSE_POINT = ROOT / "knowledge_bases" / "lighthouse_point"
SLATE_VALLEY = ROOT / "knowledge_bases" / "slate_valley"
LOCK_FLIGHT = ROOT / "knowledge_bases" / "lock_flight"
HILL_TOWN = ROOT / "knowledge_bases" / "hill_town"
HOP_VILLAGE = ROOT / "knowledge_bases" / "hop_village"
TANNERY_TOWN = ROOT / "knowledge_bases" / "tannery_town"
POTTERY_TOWN = ROOT / "knowledge_bases" / "pottery_town"
SALT_TOWN = ROOT / "knowledge_bases" / "salt_town"
HOLIDAY_CAMP = ROOT / "knowledge_bases" / "holiday_camp"
HIGHLAND_ESTATE = ROOT / "knowledge_bases" / "highland_estate"
CAVE_GORGE = ROOT / "knowledge_bases" / "cave_gorge"
PRIORY_ISLE = ROOT / "knowledge_bases" / "priory_isle"
NAVAL_DOCKYARD = ROOT / "knowledge_bases" / "naval_dockyard"
HILLFORT_VILLAGE = ROOT / "knowledge_bases" / "hillfort_village"
CANAL_TUNNEL = ROOT / "knowledge_bases" / "canal_tunnel"
CROFTING_ISLE = ROOT / "knowledge_bases" / "crofting_isle"
OBSERVATORY_HILL = ROOT / "knowledge_bases" / "observatory_hill"
BORDER_CROSSING = ROOT / "knowledge_bases" / "border_crossing"
WITHY_LEVELS = ROOT / "knowledge_bases" / "withy_levels"
BIRD_RESERVE = ROOT / "knowledge_bases" / "bird_reserve"
ARMY_CAMP = ROOT / "knowledge_bases" / "army_camp"
PILGRIM_PASS = ROOT / "knowledge_bases" / "pilgrim_pass"
SUGAR_FACTORY_TOWN = ROOT / "knowledge_bases" / "sugar_factory_town"
QUARRY_LAKE_PARK = ROOT / "knowledge_bases" / "quarry_lake_park"
MILL_RACE_TOWN = ROOT / "knowledge_bases" / "mill_race_town"
LEAD_MINING_DALE = ROOT / "knowledge_bases" / "lead_mining_dale"
RIVER_FESTIVAL = ROOT / "knowledge_bases" / "river_festival"
GARRISON_TOWN = ROOT / "knowledge_bases" / "garrison_town"
WATER_PARK = ROOT / "knowledge_bases" / "water_park"
BRICK_KILN_VILLAGE = ROOT / "knowledge_bases" / "brick_kiln_village"
STEAM_RALLY = ROOT / "knowledge_bases" / "steam_rally"
TIN_MINE_COAST = ROOT / "knowledge_bases" / "tin_mine_coast"
CITY_MARATHON = ROOT / "knowledge_bases" / "city_marathon"
CATTLE_MARKET_TOWN = ROOT / "knowledge_bases" / "cattle_market_town"
FILM_STUDIO_LOT = ROOT / "knowledge_bases" / "film_studio_lot"
BOTANIC_GARDEN = ROOT / "knowledge_bases" / "botanic_garden"
RECYCLING_DEPOT = ROOT / "knowledge_bases" / "recycling_depot"
SMOKEHOUSE_HARBOUR = ROOT / "knowledge_bases" / "smokehouse_harbour"
WIND_FARM_COAST = ROOT / "knowledge_bases" / "wind_farm_coast"
OPEN_AIR_MUSEUM = ROOT / "knowledge_bases" / "open_air_museum"
BIKE_PARK = ROOT / "knowledge_bases" / "bike_park"
BEACH_PROMENADE = ROOT / "knowledge_bases" / "beach_promenade"
SAWMILL_CAMP = ROOT / "knowledge_bases" / "sawmill_camp"
CARAVAN_PARK = ROOT / "knowledge_bases" / "caravan_park"
GLACIER_STATION = ROOT / "knowledge_bases" / "glacier_station"
TEA_ESTATE = ROOT / "knowledge_bases" / "tea_estate"
CIRCUS_QUARTERS = ROOT / "knowledge_bases" / "circus_quarters"
CEMENT_WORKS = ROOT / "knowledge_bases" / "cement_works"
CITY_FARM = ROOT / "knowledge_bases" / "city_farm"
OIL_RIG = ROOT / "knowledge_bases" / "oil_rig"
HYDRO_DAM = ROOT / "knowledge_bases" / "hydro_dam"
POLDER_VILLAGE = ROOT / "knowledge_bases" / "polder_village"
GRAIN_TERMINAL = ROOT / "knowledge_bases" / "grain_terminal"
SAFARI_PARK = ROOT / "knowledge_bases" / "safari_park"
MOUNTAIN_MONASTERY = ROOT / "knowledge_bases" / "mountain_monastery"
COPPER_SMELTER = ROOT / "knowledge_bases" / "copper_smelter"
SEWAGE_WORKS = ROOT / "knowledge_bases" / "sewage_works"
LAUNCH_SITE = ROOT / "knowledge_bases" / "launch_site"
STILT_VILLAGE = ROOT / "knowledge_bases" / "stilt_village"
CABLE_CAR_RESORT = ROOT / "knowledge_bases" / "cable_car_resort"
LANDFILL_SITE = ROOT / "knowledge_bases" / "landfill_site"
AQUARIUM_CENTRE = ROOT / "knowledge_bases" / "aquarium_centre"
FERRY_ROPEWAY_GORGE = ROOT / "knowledge_bases" / "ferry_ropeway_gorge"
OIL_REFINERY = ROOT / "knowledge_bases" / "oil_refinery"
FISH_HATCHERY = ROOT / "knowledge_bases" / "fish_hatchery"
SHIP_BREAKING_YARD = ROOT / "knowledge_bases" / "ship_breaking_yard"
HORSE_STUD = ROOT / "knowledge_bases" / "horse_stud"
DESALINATION_PLANT = ROOT / "knowledge_bases" / "desalination_plant"
SEA_FORT = ROOT / "knowledge_bases" / "sea_fort"
BUS_DEPOT = ROOT / "knowledge_bases" / "bus_depot"
ICE_RINK_ARENA = ROOT / "knowledge_bases" / "ice_rink_arena"
TEXTILE_MILL_VILLAGE = ROOT / "knowledge_bases" / "textile_mill_village"
CLIFF_RAILWAY_TOWN = ROOT / "knowledge_bases" / "cliff_railway_town"
CREAMERY = ROOT / "knowledge_bases" / "creamery"
DATA_CENTRE_CAMPUS = ROOT / "knowledge_bases" / "data_centre_campus"
WINTER_MARKET = ROOT / "knowledge_bases" / "winter_market"
ALLOTMENT_GARDENS = ROOT / "knowledge_bases" / "allotment_gardens"
BOARDING_SCHOOL = ROOT / "knowledge_bases" / "boarding_school"
TIMBER_DOCKS = ROOT / "knowledge_bases" / "timber_docks"
HOT_SPRING_RESORT = ROOT / "knowledge_bases" / "hot_spring_resort"
CAR_FACTORY = ROOT / "knowledge_bases" / "car_factory"
MOUNTAIN_HUT_TRAIL = ROOT / "knowledge_bases" / "mountain_hut_trail"
NIGHT_MARKET_BRIDGE = ROOT / "knowledge_bases" / "night_market_bridge"
MUSHROOM_FARM = ROOT / "knowledge_bases" / "mushroom_farm"
LOCK_KEEPERS_COTTAGES = ROOT / "knowledge_bases" / "lock_keepers_cottages"
HOSPICE_GROUNDS = ROOT / "knowledge_bases" / "hospice_grounds"
FAIRGROUND_PIER = ROOT / "knowledge_bases" / "fairground_pier"
MONASTERY_VINEYARD = ROOT / "knowledge_bases" / "monastery_vineyard"
SKI_JUMP_CENTRE = ROOT / "knowledge_bases" / "ski_jump_centre"
SAILING_CENTRE = ROOT / "knowledge_bases" / "sailing_centre"
AVIATION_MUSEUM = ROOT / "knowledge_bases" / "aviation_museum"
OYSTER_FISHERY = ROOT / "knowledge_bases" / "oyster_fishery"
OPAL_MINING_OUTPOST = ROOT / "knowledge_bases" / "opal_mining_outpost"
FIREWORKS_FACTORY = ROOT / "knowledge_bases" / "fireworks_factory"
RICE_TERRACE_VILLAGE = ROOT / "knowledge_bases" / "rice_terrace_village"
VERTICAL_FARM = ROOT / "knowledge_bases" / "vertical_farm"
SALMON_CANNERY = ROOT / "knowledge_bases" / "salmon_cannery"
RADIO_TELESCOPE_ARRAY = ROOT / "knowledge_bases" / "radio_telescope_array"
CRANBERRY_BOG = ROOT / "knowledge_bases" / "cranberry_bog"
DESERT_RESEARCH_STATION = ROOT / "knowledge_bases" / "desert_research_station"
LAVENDER_DISTILLERY = ROOT / "knowledge_bases" / "lavender_distillery"
TIDAL_BARRAGE = ROOT / "knowledge_bases" / "tidal_barrage"
ICE_HOTEL = ROOT / "knowledge_bases" / "ice_hotel"
GLASSWORKS_TOWN = ROOT / "knowledge_bases" / "glassworks_town"
CHOCOLATE_FACTORY_TOWN = ROOT / "knowledge_bases" / "chocolate_factory_town"
SEAWEED_COAST = ROOT / "knowledge_bases" / "seaweed_coast"
BELL_FOUNDRY_VILLAGE = ROOT / "knowledge_bases" / "bell_foundry_village"
SCOUT_JAMBOREE = ROOT / "knowledge_bases" / "scout_jamboree"
GEOTHERMAL_FIELD = ROOT / "knowledge_bases" / "geothermal_field"
SEAL_SANCTUARY = ROOT / "knowledge_bases" / "seal_sanctuary"
CIDER_MILL_FARM = ROOT / "knowledge_bases" / "cider_mill_farm"
MOTOCROSS_TRACK = ROOT / "knowledge_bases" / "motocross_track"
OLIVE_TERRACES = ROOT / "knowledge_bases" / "olive_terraces"
LIFEBOAT_STATION = ROOT / "knowledge_bases" / "lifeboat_station"
SULPHUR_MINE = ROOT / "knowledge_bases" / "sulphur_mine"
APIARY_VILLAGE = ROOT / "knowledge_bases" / "apiary_village"
BAMBOO_TEMPLE = ROOT / "knowledge_bases" / "bamboo_temple"
EXPO_SITE = ROOT / "knowledge_bases" / "expo_site"
LIDO_PARK = ROOT / "knowledge_bases" / "lido_park"
SALT_FLATS_SPEEDWAY = ROOT / "knowledge_bases" / "salt_flats_speedway"
PITHEAD_VILLAGE = ROOT / "knowledge_bases" / "pithead_village"
REGATTA_COURSE = ROOT / "knowledge_bases" / "regatta_course"
DAIRY_FARM = ROOT / "knowledge_bases" / "dairy_farm"
BALLOON_FIESTA = ROOT / "knowledge_bases" / "balloon_fiesta"
ROPE_WALK_QUAY = ROOT / "knowledge_bases" / "rope_walk_quay"
TULIP_FIELDS = ROOT / "knowledge_bases" / "tulip_fields"
OASIS_TOWN = ROOT / "knowledge_bases" / "oasis_town"
AVALANCHE_HAMLET = ROOT / "knowledge_bases" / "avalanche_hamlet"
MAPLE_SUGAR_BUSH = ROOT / "knowledge_bases" / "maple_sugar_bush"
GALVANISING_WORKS = ROOT / "knowledge_bases" / "galvanising_works"
SHOW_CAVERNS = ROOT / "knowledge_bases" / "show_caverns"
FLOATING_MARKET = ROOT / "knowledge_bases" / "floating_market"
OAST_VALLEY = ROOT / "knowledge_bases" / "oast_valley"
BRIDGE_WORKS = ROOT / "knowledge_bases" / "bridge_works"
PINE_CAMPGROUND = ROOT / "knowledge_bases" / "pine_campground"
GANNET_ISLE = ROOT / "knowledge_bases" / "gannet_isle"
RUBBER_PLANTATION = ROOT / "knowledge_bases" / "rubber_plantation"
FJORD_FERRY_VILLAGE = ROOT / "knowledge_bases" / "fjord_ferry_village"
SILK_FARM_VILLAGE = ROOT / "knowledge_bases" / "silk_farm_village"
MEDIEVAL_TOURNAMENT = ROOT / "knowledge_bases" / "medieval_tournament"
BAUXITE_MINE_PORT = ROOT / "knowledge_bases" / "bauxite_mine_port"
COFFEE_FINCA = ROOT / "knowledge_bases" / "coffee_finca"
ICE_ROAD_CAMP = ROOT / "knowledge_bases" / "ice_road_camp"
CANYON_RAFTING_BASE = ROOT / "knowledge_bases" / "canyon_rafting_base"
PEAT_RAILWAY_BOG = ROOT / "knowledge_bases" / "peat_railway_bog"
MARBLE_QUARRY_TOWN = ROOT / "knowledge_bases" / "marble_quarry_town"
CRUISE_TERMINAL = ROOT / "knowledge_bases" / "cruise_terminal"
REINDEER_HERDERS_CAMP = ROOT / "knowledge_bases" / "reindeer_herders_camp"
PRINTING_WORKS = ROOT / "knowledge_bases" / "printing_works"
CHEESE_CAVES_VILLAGE = ROOT / "knowledge_bases" / "cheese_caves_village"
SOLAR_FARM_SUBSTATION = ROOT / "knowledge_bases" / "solar_farm_substation"
SHEARING_STATION = ROOT / "knowledge_bases" / "shearing_station"
CANAL_BOATYARD = ROOT / "knowledge_bases" / "canal_boatyard"
TRANSMITTER_STATION = ROOT / "knowledge_bases" / "transmitter_station"
GOLD_DREDGE_CAMP = ROOT / "knowledge_bases" / "gold_dredge_camp"
CARAVANSERAI_OASIS = ROOT / "knowledge_bases" / "caravanserai_oasis"
AIRSHIP_HANGAR = ROOT / "knowledge_bases" / "airship_hangar"
WATCHMAKING_TOWN = ROOT / "knowledge_bases" / "watchmaking_town"
RODEO_GROUNDS = ROOT / "knowledge_bases" / "rodeo_grounds"
CORK_OAK_ESTATE = ROOT / "knowledge_bases" / "cork_oak_estate"
FISH_AUCTION_QUAY = ROOT / "knowledge_bases" / "fish_auction_quay"
VOLCANO_VILLAGE = ROOT / "knowledge_bases" / "volcano_village"
COTTON_GIN_TOWN = ROOT / "knowledge_bases" / "cotton_gin_town"
BOAT_LIFT = ROOT / "knowledge_bases" / "boat_lift"
SLED_DOG_KENNELS = ROOT / "knowledge_bases" / "sled_dog_kennels"
WINDMILL_VILLAGE = ROOT / "knowledge_bases" / "windmill_village"
VICTORIAN_PUMPING_STATION = ROOT / "knowledge_bases" / "victorian_pumping_station"
ZIPLINE_PARK = ROOT / "knowledge_bases" / "zipline_park"
HOP_KILN_FARM_MUSEUM = ROOT / "knowledge_bases" / "hop_kiln_farm_museum"
TIDE_MILL_QUAY = ROOT / "knowledge_bases" / "tide_mill_quay"
ROPEWAY_MINE_CAMP = ROOT / "knowledge_bases" / "ropeway_mine_camp"
SEA_BATHING_POOL = ROOT / "knowledge_bases" / "sea_bathing_pool"
SEAPLANE_BASE = ROOT / "knowledge_bases" / "seaplane_base"
SALT_MINE_MUSEUM = ROOT / "knowledge_bases" / "salt_mine_museum"
CRICKET_GROUND_VILLAGE = ROOT / "knowledge_bases" / "cricket_ground_village"
MUSSEL_FARM_BAY = ROOT / "knowledge_bases" / "mussel_farm_bay"
LUMBER_FLUME_VALLEY = ROOT / "knowledge_bases" / "lumber_flume_valley"
CHARCOAL_BURNERS_WOOD = ROOT / "knowledge_bases" / "charcoal_burners_wood"
RAILWAY_ROUNDHOUSE = ROOT / "knowledge_bases" / "railway_roundhouse"
BANANA_PLANTATION = ROOT / "knowledge_bases" / "banana_plantation"
PEAT_CUTTING_MOSS = ROOT / "knowledge_bases" / "peat_cutting_moss"
LIGHTHOUSE_CAUSEWAY = ROOT / "knowledge_bases" / "lighthouse_causeway"
SILK_ROAD_CARAVAN_MARKET = ROOT / "knowledge_bases" / "silk_road_caravan_market"
GRAVEL_PIT_NATURE_RESERVE = ROOT / "knowledge_bases" / "gravel_pit_nature_reserve"
HOVERCRAFT_TERMINAL = ROOT / "knowledge_bases" / "hovercraft_terminal"
STUD_DAIRY_SHOWGROUND = ROOT / "knowledge_bases" / "stud_dairy_showground"
COPPER_MINE_TAILINGS_DAM = ROOT / "knowledge_bases" / "copper_mine_tailings_dam"
FERRY_SLIPWAY_ISLAND = ROOT / "knowledge_bases" / "ferry_slipway_island"
WHALING_STATION_MUSEUM = ROOT / "knowledge_bases" / "whaling_station_museum"
SHEEPDOG_TRIALS_FIELD = ROOT / "knowledge_bases" / "sheepdog_trials_field"
TUNNEL_BORING_WORKSITE = ROOT / "knowledge_bases" / "tunnel_boring_worksite"
INDOOR_MARKET_HALL = ROOT / "knowledge_bases" / "indoor_market_hall"
WILDFIRE_BASE_CAMP = ROOT / "knowledge_bases" / "wildfire_base_camp"
GLIDER_AIRFIELD = ROOT / "knowledge_bases" / "glider_airfield"
CITRUS_PACKING_HOUSE = ROOT / "knowledge_bases" / "citrus_packing_house"
STONE_CIRCLE_HERITAGE_SITE = ROOT / "knowledge_bases" / "stone_circle_heritage_site"
WETLAND_BOARDWALK_RESERVE = ROOT / "knowledge_bases" / "wetland_boardwalk_reserve"
MAGLEV_TEST_TRACK = ROOT / "knowledge_bases" / "maglev_test_track"
SKATE_PARK_PLAZA = ROOT / "knowledge_bases" / "skate_park_plaza"
IRON_ORE_RAILHEAD = ROOT / "knowledge_bases" / "iron_ore_railhead"
BONFIRE_NIGHT_COMMON = ROOT / "knowledge_bases" / "bonfire_night_common"
PUMICE_QUARRY_ISLAND = ROOT / "knowledge_bases" / "pumice_quarry_island"
GREYHOUND_STADIUM = ROOT / "knowledge_bases" / "greyhound_stadium"
MUSIC_CONSERVATORY = ROOT / "knowledge_bases" / "music_conservatory"
VELODROME_TRACK_CENTRE = ROOT / "knowledge_bases" / "velodrome_track_centre"
POLO_CLUB_GROUND = ROOT / "knowledge_bases" / "polo_club_ground"
RUM_DISTILLERY_ESTATE = ROOT / "knowledge_bases" / "rum_distillery_estate"
GEYSER_BASIN_PARK = ROOT / "knowledge_bases" / "geyser_basin_park"
FLOWER_AUCTION_HALL = ROOT / "knowledge_bases" / "flower_auction_hall"
POLAR_RESEARCH_STATION = ROOT / "knowledge_bases" / "polar_research_station"
TRUFFLE_OAK_PLANTATION = ROOT / "knowledge_bases" / "truffle_oak_plantation"
COCOA_FERMENTARY_COOPERATIVE = ROOT / "knowledge_bases" / "cocoa_fermentary_cooperative"
ROYAL_MINT_COIN_WORKS = ROOT / "knowledge_bases" / "royal_mint_coin_works"
BOBSLEIGH_TRACK_VENUE = ROOT / "knowledge_bases" / "bobsleigh_track_venue"
SHIPBREAKING_BEACH_YARD = ROOT / "knowledge_bases" / "shipbreaking_beach_yard"
LNG_IMPORT_TERMINAL = ROOT / "knowledge_bases" / "lng_import_terminal"
SCULPTURE_PARK_ESTATE = ROOT / "knowledge_bases" / "sculpture_park_estate"
BIOGAS_FARM_DIGESTER = ROOT / "knowledge_bases" / "biogas_farm_digester"
BAZAAR_OLD_CITY_SOUK = ROOT / "knowledge_bases" / "bazaar_old_city_souk"
ROWING_LAKE_REGATTA_CENTRE = ROOT / "knowledge_bases" / "rowing_lake_regatta_centre"
ALPACA_TREKKING_FARM = ROOT / "knowledge_bases" / "alpaca_trekking_farm"
PIPE_ORGAN_CONCERT_HALL = ROOT / "knowledge_bases" / "pipe_organ_concert_hall"
HIGHRISE_CONSTRUCTION_SITE = ROOT / "knowledge_bases" / "highrise_construction_site"
MANGROVE_ECO_LODGE = ROOT / "knowledge_bases" / "mangrove_eco_lodge"
FIBRE_CABLE_FACTORY = ROOT / "knowledge_bases" / "fibre_cable_factory"
EQUESTRIAN_EVENTING_COURSE = ROOT / "knowledge_bases" / "equestrian_eventing_course"
PARAGLIDING_LAUNCH_HILL = ROOT / "knowledge_bases" / "paragliding_launch_hill"
DRINKING_WATER_TREATMENT_WORKS = ROOT / "knowledge_bases" / "drinking_water_treatment_works"
RIVER_CRUISE_SHIP = ROOT / "knowledge_bases" / "river_cruise_ship"
SEA_CLIFF_CLIMBING_CRAG = ROOT / "knowledge_bases" / "sea_cliff_climbing_crag"
PHARMACEUTICAL_PLANT = ROOT / "knowledge_bases" / "pharmaceutical_plant"
RURAL_WEDDING_VENUE = ROOT / "knowledge_bases" / "rural_wedding_venue"
WILDLIFE_RESCUE_HOSPITAL = ROOT / "knowledge_bases" / "wildlife_rescue_hospital"
AIRPORT_CARGO_CENTRE = ROOT / "knowledge_bases" / "airport_cargo_centre"
CORAL_ISLAND_DIVE_RESORT = ROOT / "knowledge_bases" / "coral_island_dive_resort"
MEAT_PROCESSING_ABATTOIR = ROOT / "knowledge_bases" / "meat_processing_abattoir"
ICE_FISHING_LAKE_CAMP = ROOT / "knowledge_bases" / "ice_fishing_lake_camp"
CINEMA_MULTIPLEX = ROOT / "knowledge_bases" / "cinema_multiplex"
HYDROGEN_FUEL_DEPOT = ROOT / "knowledge_bases" / "hydrogen_fuel_depot"
OPEN_PIT_DIAMOND_MINE = ROOT / "knowledge_bases" / "open_pit_diamond_mine"
TOBACCO_CURING_BARNS = ROOT / "knowledge_bases" / "tobacco_curing_barns"
ADVENTURE_PLAYGROUND = ROOT / "knowledge_bases" / "adventure_playground"
FLOATING_SOLAR_RESERVOIR = ROOT / "knowledge_bases" / "floating_solar_reservoir"
CIVIC_COURTHOUSE_SQUARE = ROOT / "knowledge_bases" / "civic_courthouse_square"
AIRCRAFT_CARRIER_DECK = ROOT / "knowledge_bases" / "aircraft_carrier_deck"
SOLAR_TOWER_POWER_PLANT = ROOT / "knowledge_bases" / "solar_tower_power_plant"
ROOFTOP_GARDEN_BLOCK = ROOT / "knowledge_bases" / "rooftop_garden_block"
TRUCK_STOP_WEIGH_STATION = ROOT / "knowledge_bases" / "truck_stop_weigh_station"
SCRAP_METAL_YARD = ROOT / "knowledge_bases" / "scrap_metal_yard"
TREETOP_CANOPY_WALKWAY = ROOT / "knowledge_bases" / "treetop_canopy_walkway"
HIGHLAND_GAMES_FIELD = ROOT / "knowledge_bases" / "highland_games_field"
DINOSAUR_FOSSIL_DIG_SITE = ROOT / "knowledge_bases" / "dinosaur_fossil_dig_site"
ROMAN_AMPHITHEATRE_OPERA = ROOT / "knowledge_bases" / "roman_amphitheatre_opera"
HIGH_SPEED_RAIL_STATION = ROOT / "knowledge_bases" / "high_speed_rail_station"
RICE_MILL_COOPERATIVE = ROOT / "knowledge_bases" / "rice_mill_cooperative"
SURF_BEACH_LIFEGUARD_CLUB = ROOT / "knowledge_bases" / "surf_beach_lifeguard_club"
WEST_END_THEATRE_BACKSTAGE = ROOT / "knowledge_bases" / "west_end_theatre_backstage"
COASTAL_RADAR_STATION = ROOT / "knowledge_bases" / "coastal_radar_station"
CAR_BOOT_SALE_FIELD = ROOT / "knowledge_bases" / "car_boot_sale_field"
BAMBOO_RAFT_RIVER_VILLAGE = ROOT / "knowledge_bases" / "bamboo_raft_river_village"
SHIP_CANAL_SWING_BRIDGE = ROOT / "knowledge_bases" / "ship_canal_swing_bridge"
GO_KART_TRACK = ROOT / "knowledge_bases" / "go_kart_track"
QUARANTINE_STATION_ISLAND = ROOT / "knowledge_bases" / "quarantine_station_island"
ICE_CREAM_FACTORY = ROOT / "knowledge_bases" / "ice_cream_factory"
CEMETERY_CREMATORIUM_GROUNDS = ROOT / "knowledge_bases" / "cemetery_crematorium_grounds"
PEARL_FARM_LAGOON = ROOT / "knowledge_bases" / "pearl_farm_lagoon"
MARKET_GARDEN_SMALLHOLDING = ROOT / "knowledge_bases" / "market_garden_smallholding"
MOTORWAY_BRIDGE_ROADWORKS = ROOT / "knowledge_bases" / "motorway_bridge_roadworks"
FERRIS_WHEEL_EMBANKMENT = ROOT / "knowledge_bases" / "ferris_wheel_embankment"
PEA_VINING_STATION = ROOT / "knowledge_bases" / "pea_vining_station"
ALPINE_DAIRY_PASTURE = ROOT / "knowledge_bases" / "alpine_dairy_pasture"
DRY_SKI_SLOPE_CENTRE = ROOT / "knowledge_bases" / "dry_ski_slope_centre"
VILLAGE_FETE_GREEN = ROOT / "knowledge_bases" / "village_fete_green"
PUMPED_STORAGE_CAVERN = ROOT / "knowledge_bases" / "pumped_storage_cavern"
FERRY_BRIDGE_TOLL_PLAZA = ROOT / "knowledge_bases" / "ferry_bridge_toll_plaza"
NATIONAL_ARCHIVES_REPOSITORY = ROOT / "knowledge_bases" / "national_archives_repository"
OSTRICH_FARM_VISITOR_PARK = ROOT / "knowledge_bases" / "ostrich_farm_visitor_park"
FLOATING_DRY_DOCK_YARD = ROOT / "knowledge_bases" / "floating_dry_dock_yard"
RESEARCH_REACTOR_CAMPUS = ROOT / "knowledge_bases" / "research_reactor_campus"
MAIZE_MAZE_FARM_SHOP = ROOT / "knowledge_bases" / "maize_maze_farm_shop"
DRIVE_IN_CINEMA_LOT = ROOT / "knowledge_bases" / "drive_in_cinema_lot"
ESTUARY_COCKLE_BEDS = ROOT / "knowledge_bases" / "estuary_cockle_beds"
TENNIS_CHAMPIONSHIP_GROUNDS = ROOT / "knowledge_bases" / "tennis_championship_grounds"
KASBAH_MOUNTAIN_VILLAGE = ROOT / "knowledge_bases" / "kasbah_mountain_village"
LIGHTHOUSE_KEEPERS_ISLAND = ROOT / "knowledge_bases" / "lighthouse_keepers_island"
BRASS_BAND_CONTEST_HALL = ROOT / "knowledge_bases" / "brass_band_contest_hall"
CANAL_LIFT_BRIDGE_VILLAGE = ROOT / "knowledge_bases" / "canal_lift_bridge_village"
HILL_FORT_ARCHAEOLOGY_CAMP = ROOT / "knowledge_bases" / "hill_fort_archaeology_camp"
SEASIDE_CRAZY_GOLF_FRONT = ROOT / "knowledge_bases" / "seaside_crazy_golf_front"
SUGAR_BEET_FACTORY_CAMPAIGN = ROOT / "knowledge_bases" / "sugar_beet_factory_campaign"
MOUNTAIN_BIKE_RACE_VILLAGE = ROOT / "knowledge_bases" / "mountain_bike_race_village"
CITY_LIBRARY_AND_ARCHIVE = ROOT / "knowledge_bases" / "city_library_and_archive"
ONSEN_HOT_SPRING_TOWN = ROOT / "knowledge_bases" / "onsen_hot_spring_town"
SAND_DUNE_BUGGY_PARK = ROOT / "knowledge_bases" / "sand_dune_buggy_park"
CATTLE_FEEDLOT = ROOT / "knowledge_bases" / "cattle_feedlot"
POSTAL_SORTING_CENTRE = ROOT / "knowledge_bases" / "postal_sorting_centre"
OFFSHORE_WIND_SERVICE_PORT = ROOT / "knowledge_bases" / "offshore_wind_service_port"
MONORAIL_THEME_RESORT = ROOT / "knowledge_bases" / "monorail_theme_resort"
WASTE_INCINERATOR_PLANT = ROOT / "knowledge_bases" / "waste_incinerator_plant"
CARNIVAL_PARADE_ROUTE = ROOT / "knowledge_bases" / "carnival_parade_route"


def _set(path: str, kb: Path, tag: str, counts: dict[str, int], sep: str = "-") -> dict:
    short = {"standard": "s", "messy": "m", "advanced_messy": "a"}
    return {"file": GROUNDING / path, "kb": kb, "counts": counts,
            "prefixes": {regime: f"{tag}{sep}{short[regime]}-" for regime in counts}}


EVEN = {"standard": 40, "messy": 40, "advanced_messy": 40}
THIRTY = {"standard": 30, "messy": 30, "advanced_messy": 30}  # the 90-report set of an unseen KB
QUARTER = {"standard": 25, "messy": 25, "advanced_messy": 25}
TWENTY = {"standard": 20, "messy": 20, "advanced_messy": 20}  # the 60-report set of an unseen KB


SETS = {
    "dev2/market_square": _set("dev2/market_square.jsonl", MARKET_SQUARE, "d2",
                               {"standard": 40, "messy": 40, "advanced_messy": 40}),
    "dev2/riverbend": _set("dev2/riverbend.jsonl", RIVERBEND, "d2-rb",
                           {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev3/market_square": _set("dev3/market_square.jsonl", MARKET_SQUARE, "d3", {"messy": 40, "advanced_messy": 60}),
    "dev4/market_square": _set("dev4/market_square.jsonl", MARKET_SQUARE, "d4",
                               {"standard": 40, "messy": 40, "advanced_messy": 30}),
    "dev4/riverbend": _set("dev4/riverbend.jsonl", RIVERBEND, "d4-rb", {"standard": 15, "messy": 15, "advanced_messy": 15}),
    "dev5/market_square": _set("dev5/market_square.jsonl", MARKET_SQUARE, "d5", EVEN, sep=""),
    "dev5/riverbend": _set("dev5/riverbend.jsonl", RIVERBEND, "d5r", {"standard": 30, "messy": 30, "advanced_messy": 30},
                           sep=""),
    "dev5/harbourside": _set("dev5/harbourside.jsonl", HARBOURSIDE, "hb", EVEN, sep=""),
    "dev6/market_square": _set("dev6/market_square.jsonl", MARKET_SQUARE, "d6",
                               {"standard": 30, "messy": 50, "advanced_messy": 40}, sep=""),
    "dev6/northgate": _set("dev6/northgate.jsonl", NORTHGATE, "ng", {"standard": 30, "messy": 30, "advanced_messy": 30},
                           sep=""),
    "dev6/quarrytown": _set("dev6/quarrytown.jsonl", QUARRYTOWN, "qt", EVEN, sep=""),
    "dev7/market_square": _set("dev7/market_square.jsonl", MARKET_SQUARE, "d7",
                               {"standard": 30, "messy": 50, "advanced_messy": 40}, sep=""),
    "dev7/saltmarsh_airfield": _set("dev7/saltmarsh_airfield.jsonl", SALTMARSH, "sa",
                                    {"standard": 30, "messy": 50, "advanced_messy": 40}, sep=""),
    "dev8/market_square": _set("dev8/market_square.jsonl", MARKET_SQUARE, "d8",
                               {"standard": 20, "messy": 60, "advanced_messy": 40}, sep=""),
    "dev8/market_square_b": _set("dev8/market_square_b.jsonl", MARKET_SQUARE, "d8b",
                                 {"standard": 20, "messy": 70, "advanced_messy": 30}, sep=""),
    "dev9/market_square": _set("dev9/market_square.jsonl", MARKET_SQUARE, "d9",
                               {"standard": 10, "messy": 50, "advanced_messy": 60}, sep=""),
    "dev9/market_square_b": _set("dev9/market_square_b.jsonl", MARKET_SQUARE, "d9b",
                                 {"standard": 10, "messy": 60, "advanced_messy": 50}, sep=""),
    "dev10/market_square": _set("dev10/market_square.jsonl", MARKET_SQUARE, "d10",
                                {"standard": 15, "messy": 60, "advanced_messy": 45}, sep=""),
    "dev10/market_square_b": _set("dev10/market_square_b.jsonl", MARKET_SQUARE, "d10b",
                                  {"standard": 15, "messy": 55, "advanced_messy": 50}, sep=""),
    "dev11/alpine_village": _set("dev11/alpine_village.jsonl", ALPINE, "av",
                                 THIRTY),
    "dev11/container_port": _set("dev11/container_port.jsonl", PORT, "cp",
                                 THIRTY),
    "dev12/delta_town": _set("dev12/delta_town.jsonl", DELTA, "dt", THIRTY),
    "dev12/metro_interchange": _set("dev12/metro_interchange.jsonl", METRO, "mi",
                                    THIRTY),
    "dev13/hillside_quake": _set("dev13/hillside_quake.jsonl", HILLSIDE, "hq",
                                 THIRTY),
    "dev13/chemical_works": _set("dev13/chemical_works.jsonl", CHEMICAL, "cw",
                                 THIRTY),
    "dev14/festival_site": _set("dev14/festival_site.jsonl", FESTIVAL, "fs",
                                THIRTY),
    "dev14/ferry_ship": _set("dev14/ferry_ship.jsonl", FERRY, "fr", THIRTY),
    "dev15/market_square": _set("dev15/market_square.jsonl", MARKET_SQUARE, "d15",
                                {"standard": 20, "messy": 55, "advanced_messy": 45}, sep=""),
    "dev15/lakeside_campground": _set("dev15/lakeside_campground.jsonl", CAMPGROUND, "lc",
                                      THIRTY),
    "dev15/road_tunnel": _set("dev15/road_tunnel.jsonl", TUNNEL, "rt", THIRTY),
    "dev16/football_stadium": _set("dev16/football_stadium.jsonl", STADIUM, "fb",
                                   THIRTY),
    "dev16/shopping_mall": _set("dev16/shopping_mall.jsonl", MALL, "sm", THIRTY),
    "dev17/market_square": _set("dev17/market_square.jsonl", MARKET_SQUARE, "d17",
                                {"standard": 20, "messy": 55, "advanced_messy": 45}, sep=""),
    "dev17/city_zoo": _set("dev17/city_zoo.jsonl", ZOO, "zo", THIRTY),
    "dev18/market_square": _set("dev18/market_square.jsonl", MARKET_SQUARE, "d18",
                                {"standard": 10, "messy": 70, "advanced_messy": 40}, sep=""),
    "dev18/seaside_pier": _set("dev18/seaside_pier.jsonl", PIER, "sp", THIRTY),
    "dev18/old_town": _set("dev18/old_town.jsonl", OLD_TOWN, "ot", THIRTY),
    "dev19/market_square": _set("dev19/market_square.jsonl", MARKET_SQUARE, "d19",
                                {"standard": 10, "messy": 50, "advanced_messy": 60}, sep=""),
    "dev19/industrial_estate": _set("dev19/industrial_estate.jsonl", ESTATE, "ie",
                                    THIRTY),
    "dev19/farm_village": _set("dev19/farm_village.jsonl", FARM, "fv", THIRTY),
    "dev20/market_square": _set("dev20/market_square.jsonl", MARKET_SQUARE, "d20",
                                {"standard": 10, "messy": 60, "advanced_messy": 30}, sep=""),
    "dev20/university_campus": _set("dev20/university_campus.jsonl", CAMPUS, "uc",
                                    THIRTY),
    "dev21/market_square": _set("dev21/market_square.jsonl", MARKET_SQUARE, "d21",
                                {"standard": 5, "messy": 60, "advanced_messy": 15}, sep=""),
    "dev21/mountain_railway": _set("dev21/mountain_railway.jsonl", RAILWAY, "mr",
                                   {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev17/hospital_campus": _set("dev17/hospital_campus.jsonl", HOSPITAL, "hc",
                                  THIRTY),
    "dev22/market_square": _set("dev22/market_square.jsonl", MARKET_SQUARE, "d22",
                                {"standard": 5, "messy": 70, "advanced_messy": 25}, sep=""),
    "dev22/canal_wharf": _set("dev22/canal_wharf.jsonl", CANAL, "cw22",
                              {"standard": 25, "messy": 30, "advanced_messy": 35}),
    "dev22/housing_estate": _set("dev22/housing_estate.jsonl", HOUSING, "he",
                                 {"standard": 20, "messy": 45, "advanced_messy": 25}),
    "dev23/market_square": _set("dev23/market_square.jsonl", MARKET_SQUARE, "d23",
                                {"standard": 10, "messy": 50, "advanced_messy": 40}, sep=""),
    "dev23/coastal_village": _set("dev23/coastal_village.jsonl", COASTAL, "cv", THIRTY),
    "dev24/market_square": _set("dev24/market_square.jsonl", MARKET_SQUARE, "d24",
                                {"standard": 15, "messy": 60, "advanced_messy": 35}, sep=""),
    "dev24/market_square_b": _set("dev24/market_square_b.jsonl", MARKET_SQUARE, "d24b", EVEN, sep=""),
    "dev24/river_port_market": _set("dev24/river_port_market.jsonl", RIVER_PORT, "rpm", THIRTY),
    "dev25/market_square": _set("dev25/market_square.jsonl", MARKET_SQUARE, "d25",
                                {"standard": 30, "messy": 50, "advanced_messy": 40}, sep=""),
    "dev25/cathedral_close": _set("dev25/cathedral_close.jsonl", CATHEDRAL, "cc", THIRTY),
    "dev26/market_square": _set("dev26/market_square.jsonl", MARKET_SQUARE, "d26",
                                {"standard": 10, "messy": 60, "advanced_messy": 30}, sep=""),
    "dev26/theme_park": _set("dev26/theme_park.jsonl", THEME_PARK, "tp", THIRTY),
    "dev26/motorway_services": _set("dev26/motorway_services.jsonl", SERVICES, "ms26", THIRTY),
    "dev27/market_square": _set("dev27/market_square.jsonl", MARKET_SQUARE, "d27", EVEN, sep=""),
    "dev27/reservoir_valley": _set("dev27/reservoir_valley.jsonl", RESERVOIR, "rv", THIRTY),
    "dev28/market_square": _set("dev28/market_square.jsonl", MARKET_SQUARE, "d28",
                                {"standard": 30, "messy": 30, "advanced_messy": 30}, sep=""),
    "dev28/airport_terminal": _set("dev28/airport_terminal.jsonl", AIRPORT, "at",
                                   {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev29/market_square": _set("dev29/market_square.jsonl", MARKET_SQUARE, "d29",
                                {"standard": 10, "messy": 50, "advanced_messy": 10}, sep=""),
    "dev29/ski_town": _set("dev29/ski_town.jsonl", SKI_TOWN, "st",
                           {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev30/market_square": _set("dev30/market_square.jsonl", MARKET_SQUARE, "d30",
                                {"standard": 10, "messy": 70, "advanced_messy": 20}, sep=""),
    "dev30/market_square_b": _set("dev30/market_square_b.jsonl", MARKET_SQUARE, "d30b",
                                  {"standard": 10, "messy": 30, "advanced_messy": 50}, sep=""),
    "dev30/spa_town": _set("dev30/spa_town.jsonl", SPA_TOWN, "sp30",
                           {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev31/market_square": _set("dev31/market_square.jsonl", MARKET_SQUARE, "d31",
                                {"standard": 10, "messy": 70, "advanced_messy": 20}, sep=""),
    "dev31/market_square_b": _set("dev31/market_square_b.jsonl", MARKET_SQUARE, "d31b",
                                  {"standard": 50, "messy": 50, "advanced_messy": 50}, sep=""),
    "dev31/market_town": _set("dev31/market_town.jsonl", MARKET_TOWN, "mt31",
                              {"standard": 20, "messy": 45, "advanced_messy": 25}),
    "dev32/market_square": _set("dev32/market_square.jsonl", MARKET_SQUARE, "d32",
                                {"standard": 10, "messy": 70, "advanced_messy": 20}, sep=""),
    "dev32/island_harbour": _set("dev32/island_harbour.jsonl", ISLAND, "ih32",
                                 {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev33/market_square": _set("dev33/market_square.jsonl", MARKET_SQUARE, "d33",
                                {"standard": 20, "messy": 50, "advanced_messy": 30}, sep=""),
    "dev33/riverbend": _set("dev33/riverbend.jsonl", RIVERBEND, "d33r",
                            {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev34/market_square": _set("dev34/market_square.jsonl", MARKET_SQUARE, "d34", EVEN, sep=""),
    "dev34/riverbend": _set("dev34/riverbend.jsonl", RIVERBEND, "d34r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev35/market_square": _set("dev35/market_square.jsonl", MARKET_SQUARE, "d35m", EVEN),
    "dev35/riverbend": _set("dev35/riverbend.jsonl", RIVERBEND, "d35r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev35/castle_town": _set("dev35/castle_town.jsonl", CASTLE_TOWN, "ct35", THIRTY),
    "dev35/science_park": _set("dev35/science_park.jsonl", SCIENCE_PARK, "sp35", THIRTY),
    "dev36/market_square": _set("dev36/market_square.jsonl", MARKET_SQUARE, "d36m", THIRTY),
    "dev36/rail_yard": _set("dev36/rail_yard.jsonl", RAIL_YARD, "ry36", THIRTY),
    "dev36/wine_estate": _set("dev36/wine_estate.jsonl", WINE_ESTATE, "we36", THIRTY),
    "dev37/market_square": _set("dev37/market_square.jsonl", MARKET_SQUARE, "d37m", THIRTY),
    "dev37/racecourse": _set("dev37/racecourse.jsonl", RACECOURSE, "d37r", THIRTY),
    "dev37/mining_town": _set("dev37/mining_town.jsonl", MINING_TOWN, "d37t", THIRTY),
    "dev38/market_square": _set("dev38/market_square.jsonl", MARKET_SQUARE, "d38m", EVEN),
    "dev38/riverbend": _set("dev38/riverbend.jsonl", RIVERBEND, "d38r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev38/tornado_suburb": _set("dev38/tornado_suburb.jsonl", TORNADO, "d38t", THIRTY),
    "dev38/ash_island": _set("dev38/ash_island.jsonl", ASH_ISLAND, "d38i", THIRTY),
    "dev39/market_square": _set("dev39/market_square.jsonl", MARKET_SQUARE, "d39m", THIRTY),
    "dev39/tower_block": _set("dev39/tower_block.jsonl", TOWER_BLOCK, "d39t", THIRTY),
    "dev39/refugee_camp": _set("dev39/refugee_camp.jsonl", REFUGEE_CAMP, "d39c", THIRTY),
    "dev40/hospital_tower": _set("dev40/hospital_tower.jsonl", HOSPITAL_TOWER, "d40h", THIRTY),
    "dev41/market_square": _set("dev41/market_square.jsonl", MARKET_SQUARE, "d41m", EVEN),
    "dev41/riverbend": _set("dev41/riverbend.jsonl", RIVERBEND, "d41r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev41/county_prison": _set("dev41/county_prison.jsonl", COUNTY_PRISON, "d41p", THIRTY),
    "dev41/coast_road": _set("dev41/coast_road.jsonl", COAST_ROAD, "d41c", THIRTY),
    "dev42/market_square": _set("dev42/market_square.jsonl", MARKET_SQUARE, "d42m", QUARTER),
    "dev42/market_square_b": _set("dev42/market_square_b.jsonl", MARKET_SQUARE, "d42b", QUARTER),
    "dev42/riverbend": _set("dev42/riverbend.jsonl", RIVERBEND, "d42r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev42/forest_park": _set("dev42/forest_park.jsonl", FOREST_PARK, "d42f", THIRTY),
    "dev43/market_square": _set("dev43/market_square.jsonl", MARKET_SQUARE, "d43m",
                                {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev43/market_square_b": _set("dev43/market_square_b.jsonl", MARKET_SQUARE, "d43b",
                                  {"standard": 25, "messy": 35, "advanced_messy": 30}),
    "dev43/riverbend": _set("dev43/riverbend.jsonl", RIVERBEND, "d43r",
                            {"standard": 25, "messy": 35, "advanced_messy": 30}),
    "dev43/dockside_estate": _set("dev43/dockside_estate.jsonl", DOCKSIDE, "d43d", THIRTY),
    "dev44/market_square": _set("dev44/market_square.jsonl", MARKET_SQUARE, "d44m",
                                {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev44/riverbend": _set("dev44/riverbend.jsonl", RIVERBEND, "d44r",
                            {"standard": 20, "messy": 30, "advanced_messy": 25}),
    "dev44/hill_farm_show": _set("dev44/hill_farm_show.jsonl", HILL_FARM, "d44h", THIRTY),
    "dev45/market_square": _set("dev45/market_square.jsonl", MARKET_SQUARE, "d45m",
                                {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev45/riverbend": _set("dev45/riverbend.jsonl", RIVERBEND, "d45r",
                            {"standard": 20, "messy": 30, "advanced_messy": 25}),
    "dev45/distillery_glen": _set("dev45/distillery_glen.jsonl", DISTILLERY, "dg", THIRTY),
    "dev45/retirement_village": _set("dev45/retirement_village.jsonl", RETIREMENT, "rvg", THIRTY),
    "dev46/market_square_vocab": _set("dev46/market_square_vocab.jsonl", MARKET_SQUARE, "d46v", EVEN),
    "dev46/riverbend_vocab": _set("dev46/riverbend_vocab.jsonl", RIVERBEND, "d46rv", THIRTY),
    "dev47/market_square": _set("dev47/market_square.jsonl", MARKET_SQUARE, "d47m", THIRTY),
    "dev47/riverbend": _set("dev47/riverbend.jsonl", RIVERBEND, "d47r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev48/market_square": _set("dev48/market_square.jsonl", MARKET_SQUARE, "d48m",
                                {"standard": 20, "messy": 45, "advanced_messy": 25}),
    "dev48/riverbend": _set("dev48/riverbend.jsonl", RIVERBEND, "d48r",
                            {"standard": 20, "messy": 35, "advanced_messy": 20}),
    "dev48/ferry_terminal_town": _set("dev48/ferry_terminal_town.jsonl", FERRY_TOWN, "ft", THIRTY),
    "dev49/market_square": _set("dev49/market_square.jsonl", MARKET_SQUARE, "d49m",
                                {"standard": 25, "messy": 25, "advanced_messy": 25}),
    "dev49/riverbend": _set("dev49/riverbend.jsonl", RIVERBEND, "d49r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev50/market_square": _set("dev50/market_square.jsonl", MARKET_SQUARE, "d50m",
                                {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev50/riverbend": _set("dev50/riverbend.jsonl", RIVERBEND, "d50r",
                            {"standard": 20, "messy": 30, "advanced_messy": 25}),
    "dev50/moorland_village": _set("dev50/moorland_village.jsonl", MOORLAND, "mv", THIRTY),
    "dev51/market_square": _set("dev51/market_square.jsonl", MARKET_SQUARE, "d51m",
                                {"standard": 20, "messy": 40, "advanced_messy": 30}),
    "dev51/riverbend": _set("dev51/riverbend.jsonl", RIVERBEND, "d51r",
                            {"standard": 20, "messy": 30, "advanced_messy": 25}),
    "dev51/glasshouse_suburb": _set("dev51/glasshouse_suburb.jsonl", GLASSHOUSE, "gs51", THIRTY),
    "dev52/market_square": _set("dev52/market_square.jsonl", MARKET_SQUARE, "d52m", QUARTER),
    "dev52/riverbend": _set("dev52/riverbend.jsonl", RIVERBEND, "d52r",
                            {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev52/estuary_marina": _set("dev52/estuary_marina.jsonl", ESTUARY, "em52",
                                 {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev53/golf_resort": _set("dev53/golf_resort.jsonl", GOLF, "gr53", {"standard": 20, "messy": 20, "advanced_messy": 20}),
    "dev54/papermill_valley": _set("dev54/papermill_valley.jsonl", PAPERMILL, "pv54", TWENTY),
    "dev54/clifftop_park": _set("dev54/clifftop_park.jsonl", CLIFFTOP, "cp54", TWENTY),
    "dev54/tramway_junction": _set("dev54/tramway_junction.jsonl", TRAMWAY, "tj54", TWENTY),
    "dev55/racing_circuit": _set("dev55/racing_circuit.jsonl", CIRCUIT, "rc55", TWENTY),
    "dev55/abbey_village": _set("dev55/abbey_village.jsonl", ABBEY, "av55", TWENTY),
    "dev56/walled_city": _set("dev56/walled_city.jsonl", WALLED_CITY, "wc56", TWENTY),
    "dev56/steelworks_town": _set("dev56/steelworks_town.jsonl", STEELWORKS, "sw56", TWENTY),
    "dev57/tidal_isle": _set("dev57/tidal_isle.jsonl", TIDAL_ISLE, "ti57", TWENTY),
    "dev57/new_town": _set("dev57/new_town.jsonl", NEW_TOWN, "nt57", TWENTY),
    "dev58/brackenford": _set("dev58/brackenford.jsonl", BRACKENFORD, "bf58", TWENTY),
    "dev59/thornwater": _set("dev59/thornwater.jsonl", THORNWATER, "tw59", {"standard": 30, "messy": 15, "advanced_messy": 15}),
    "dev60/shipyard_town": _set("dev60/shipyard_town.jsonl", SHIPYARD, "sy60", TWENTY, sep=""),
    "dev60/orchard_valley": _set("dev60/orchard_valley.jsonl", ORCHARD, "ov60", TWENTY, sep=""),
    "dev61/viaduct_town": _set("dev61/viaduct_town.jsonl", VIADUCT, "vt61", {"standard": 30, "messy": 15, "advanced_messy": 15},
                               sep=""),
    "dev61/power_station": _set("dev61/power_station.jsonl", POWER_STATION, "ps61", TWENTY, sep=""),
    "dev62/fen_town": _set("dev62/fen_town.jsonl", FEN_TOWN, "ft62", TWENTY, sep=""),
    "dev63/brewery_town": _set("dev63/brewery_town.jsonl", BREWERY_TOWN, "bt63", TWENTY, sep=""),
    "dev63/lighthouse_point": _set("dev63/lighthouse_point.jsonl", LIGHTHOUSE_POINT, "lp63", TWENTY, sep=""),
    "dev64/slate_valley": _set("dev64/slate_valley.jsonl", SLATE_VALLEY, "sv64", TWENTY, sep=""),
    "dev65/lock_flight": _set("dev65/lock_flight.jsonl", LOCK_FLIGHT, "lf65", TWENTY, sep=""),
    "dev65/hill_town": _set("dev65/hill_town.jsonl", HILL_TOWN, "ht65", TWENTY, sep=""),
    "dev66/hop_village": _set("dev66/hop_village.jsonl", HOP_VILLAGE, "hv66", TWENTY, sep=""),
    "dev66/tannery_town": _set("dev66/tannery_town.jsonl", TANNERY_TOWN, "tt66", TWENTY, sep=""),
    "dev66/pottery_town": _set("dev66/pottery_town.jsonl", POTTERY_TOWN, "pt66", TWENTY, sep=""),
    "dev67/salt_town": _set("dev67/salt_town.jsonl", SALT_TOWN, "st67", TWENTY, sep=""),
    "dev67/holiday_camp": _set("dev67/holiday_camp.jsonl", HOLIDAY_CAMP, "hc67", TWENTY, sep=""),
    "dev67/highland_estate": _set("dev67/highland_estate.jsonl", HIGHLAND_ESTATE, "he67", TWENTY, sep=""),
    "dev68/cave_gorge": _set("dev68/cave_gorge.jsonl", CAVE_GORGE, "cg68", TWENTY, sep=""),
    "dev68/priory_isle": _set("dev68/priory_isle.jsonl", PRIORY_ISLE, "pi68", TWENTY, sep=""),
    "dev68/naval_dockyard": _set("dev68/naval_dockyard.jsonl", NAVAL_DOCKYARD, "nd68", TWENTY, sep=""),
    "dev69/hillfort_village": _set("dev69/hillfort_village.jsonl", HILLFORT_VILLAGE, "hf69", TWENTY, sep=""),
    "dev69/canal_tunnel": _set("dev69/canal_tunnel.jsonl", CANAL_TUNNEL, "ct69", TWENTY, sep=""),
    "dev69/crofting_isle": _set("dev69/crofting_isle.jsonl", CROFTING_ISLE, "ci69", TWENTY, sep=""),
    "dev70/observatory_hill": _set("dev70/observatory_hill.jsonl", OBSERVATORY_HILL, "oh70", TWENTY, sep=""),
    "dev70/border_crossing": _set("dev70/border_crossing.jsonl", BORDER_CROSSING, "bc70", TWENTY, sep=""),
    "dev70/withy_levels": _set("dev70/withy_levels.jsonl", WITHY_LEVELS, "wl70", TWENTY, sep=""),
    "dev71/bird_reserve": _set("dev71/bird_reserve.jsonl", BIRD_RESERVE, "br71", TWENTY, sep=""),
    "dev71/army_camp": _set("dev71/army_camp.jsonl", ARMY_CAMP, "ac71", TWENTY, sep=""),
    "dev71/pilgrim_pass": _set("dev71/pilgrim_pass.jsonl", PILGRIM_PASS, "pp71", TWENTY, sep=""),
    "dev72/sugar_factory_town": _set("dev72/sugar_factory_town.jsonl", SUGAR_FACTORY_TOWN, "sf72", TWENTY, sep=""),
    "dev72/quarry_lake_park": _set("dev72/quarry_lake_park.jsonl", QUARRY_LAKE_PARK, "ql72", TWENTY, sep=""),
    "dev72/mill_race_town": _set("dev72/mill_race_town.jsonl", MILL_RACE_TOWN, "mr72", TWENTY, sep=""),
    "dev73/lead_mining_dale": _set("dev73/lead_mining_dale.jsonl", LEAD_MINING_DALE, "ld73", TWENTY, sep=""),
    "dev73/river_festival": _set("dev73/river_festival.jsonl", RIVER_FESTIVAL, "rf73", TWENTY, sep=""),
    "dev73/garrison_town": _set("dev73/garrison_town.jsonl", GARRISON_TOWN, "gt73", TWENTY, sep=""),
    "dev74/water_park": _set("dev74/water_park.jsonl", WATER_PARK, "wp74", TWENTY, sep=""),
    "dev74/brick_kiln_village": _set("dev74/brick_kiln_village.jsonl", BRICK_KILN_VILLAGE, "bk74", TWENTY, sep=""),
    "dev74/steam_rally": _set("dev74/steam_rally.jsonl", STEAM_RALLY, "sr74", TWENTY, sep=""),
    "dev74/tin_mine_coast": _set("dev74/tin_mine_coast.jsonl", TIN_MINE_COAST, "tm74", TWENTY, sep=""),
    "dev75/city_marathon": _set("dev75/city_marathon.jsonl", CITY_MARATHON, "cm75", TWENTY, sep=""),
    "dev75/cattle_market_town": _set("dev75/cattle_market_town.jsonl", CATTLE_MARKET_TOWN, "ct75", TWENTY, sep=""),
    "dev75/film_studio_lot": _set("dev75/film_studio_lot.jsonl", FILM_STUDIO_LOT, "fs75", TWENTY, sep=""),
    "dev76/botanic_garden": _set("dev76/botanic_garden.jsonl", BOTANIC_GARDEN, "bg76", TWENTY, sep=""),
    "dev76/recycling_depot": _set("dev76/recycling_depot.jsonl", RECYCLING_DEPOT, "rd76", TWENTY, sep=""),
    "dev76/smokehouse_harbour": _set("dev76/smokehouse_harbour.jsonl", SMOKEHOUSE_HARBOUR, "sh76", TWENTY, sep=""),
    "dev76/wind_farm_coast": _set("dev76/wind_farm_coast.jsonl", WIND_FARM_COAST, "wf76", TWENTY, sep=""),
    "dev77/open_air_museum": _set("dev77/open_air_museum.jsonl", OPEN_AIR_MUSEUM, "oa77", TWENTY, sep=""),
    "dev77/bike_park": _set("dev77/bike_park.jsonl", BIKE_PARK, "bp77", TWENTY, sep=""),
    "dev77/beach_promenade": _set("dev77/beach_promenade.jsonl", BEACH_PROMENADE, "bh77", TWENTY, sep=""),
    "dev78/sawmill_camp": _set("dev78/sawmill_camp.jsonl", SAWMILL_CAMP, "sm78", TWENTY, sep=""),
    "dev78/caravan_park": _set("dev78/caravan_park.jsonl", CARAVAN_PARK, "cv78", TWENTY, sep=""),
    "dev78/glacier_station": _set("dev78/glacier_station.jsonl", GLACIER_STATION, "gl78", TWENTY, sep=""),
    "dev78/tea_estate": _set("dev78/tea_estate.jsonl", TEA_ESTATE, "te78", TWENTY, sep=""),
    "dev79/circus_quarters": _set("dev79/circus_quarters.jsonl", CIRCUS_QUARTERS, "cq79", TWENTY, sep=""),
    "dev79/cement_works": _set("dev79/cement_works.jsonl", CEMENT_WORKS, "cw79", TWENTY, sep=""),
    "dev79/city_farm": _set("dev79/city_farm.jsonl", CITY_FARM, "cf79", TWENTY, sep=""),
    "dev80/oil_rig": _set("dev80/oil_rig.jsonl", OIL_RIG, "or80", TWENTY, sep=""),
    "dev80/hydro_dam": _set("dev80/hydro_dam.jsonl", HYDRO_DAM, "hd80", TWENTY, sep=""),
    "dev80/polder_village": _set("dev80/polder_village.jsonl", POLDER_VILLAGE, "pv80", TWENTY, sep=""),
    "dev80/grain_terminal": _set("dev80/grain_terminal.jsonl", GRAIN_TERMINAL, "gt80", TWENTY, sep=""),
    "dev81/safari_park": _set("dev81/safari_park.jsonl", SAFARI_PARK, "sp81", TWENTY, sep=""),
    "dev81/mountain_monastery": _set("dev81/mountain_monastery.jsonl", MOUNTAIN_MONASTERY, "mm81", TWENTY, sep=""),
    "dev81/copper_smelter": _set("dev81/copper_smelter.jsonl", COPPER_SMELTER, "cs81", TWENTY, sep=""),
    "dev82/sewage_works": _set("dev82/sewage_works.jsonl", SEWAGE_WORKS, "sw82", TWENTY, sep=""),
    "dev82/launch_site": _set("dev82/launch_site.jsonl", LAUNCH_SITE, "ls82", TWENTY, sep=""),
    "dev82/stilt_village": _set("dev82/stilt_village.jsonl", STILT_VILLAGE, "sv82", TWENTY, sep=""),
    "dev82/cable_car_resort": _set("dev82/cable_car_resort.jsonl", CABLE_CAR_RESORT, "cc82", TWENTY, sep=""),
    "dev83/landfill_site": _set("dev83/landfill_site.jsonl", LANDFILL_SITE, "lf83", TWENTY, sep=""),
    "dev83/aquarium_centre": _set("dev83/aquarium_centre.jsonl", AQUARIUM_CENTRE, "aq83", TWENTY, sep=""),
    "dev83/ferry_ropeway_gorge": _set("dev83/ferry_ropeway_gorge.jsonl", FERRY_ROPEWAY_GORGE, "fg83", TWENTY, sep=""),
    "dev84/oil_refinery": _set("dev84/oil_refinery.jsonl", OIL_REFINERY, "or84", TWENTY, sep=""),
    "dev84/fish_hatchery": _set("dev84/fish_hatchery.jsonl", FISH_HATCHERY, "fh84", TWENTY, sep=""),
    "dev84/ship_breaking_yard": _set("dev84/ship_breaking_yard.jsonl", SHIP_BREAKING_YARD, "sb84", TWENTY, sep=""),
    "dev84/horse_stud": _set("dev84/horse_stud.jsonl", HORSE_STUD, "hs84", TWENTY, sep=""),
    "dev85/desalination_plant": _set("dev85/desalination_plant.jsonl", DESALINATION_PLANT, "dp85", TWENTY, sep=""),
    "dev85/sea_fort": _set("dev85/sea_fort.jsonl", SEA_FORT, "sf85", TWENTY, sep=""),
    "dev85/bus_depot": _set("dev85/bus_depot.jsonl", BUS_DEPOT, "bd85", TWENTY, sep=""),
    "dev86/ice_rink_arena": _set("dev86/ice_rink_arena.jsonl", ICE_RINK_ARENA, "ir86", TWENTY, sep=""),
    "dev86/textile_mill_village": _set("dev86/textile_mill_village.jsonl", TEXTILE_MILL_VILLAGE, "tm86", TWENTY, sep=""),
    "dev86/cliff_railway_town": _set("dev86/cliff_railway_town.jsonl", CLIFF_RAILWAY_TOWN, "cl86", TWENTY, sep=""),
    "dev86/creamery": _set("dev86/creamery.jsonl", CREAMERY, "cy86", TWENTY, sep=""),
    "dev87/data_centre_campus": _set("dev87/data_centre_campus.jsonl", DATA_CENTRE_CAMPUS, "dc87", TWENTY, sep=""),
    "dev87/winter_market": _set("dev87/winter_market.jsonl", WINTER_MARKET, "wm87", TWENTY, sep=""),
    "dev87/allotment_gardens": _set("dev87/allotment_gardens.jsonl", ALLOTMENT_GARDENS, "ag87", TWENTY, sep=""),
    "dev88/boarding_school": _set("dev88/boarding_school.jsonl", BOARDING_SCHOOL, "bs88", TWENTY, sep=""),
    "dev88/timber_docks": _set("dev88/timber_docks.jsonl", TIMBER_DOCKS, "td88", TWENTY, sep=""),
    "dev88/hot_spring_resort": _set("dev88/hot_spring_resort.jsonl", HOT_SPRING_RESORT, "hr88", TWENTY, sep=""),
    "dev88/car_factory": _set("dev88/car_factory.jsonl", CAR_FACTORY, "cf88", TWENTY, sep=""),
    "dev89/mountain_hut_trail": _set("dev89/mountain_hut_trail.jsonl", MOUNTAIN_HUT_TRAIL, "mh89", TWENTY, sep=""),
    "dev89/night_market_bridge": _set("dev89/night_market_bridge.jsonl", NIGHT_MARKET_BRIDGE, "nm89", TWENTY, sep=""),
    "dev89/mushroom_farm": _set("dev89/mushroom_farm.jsonl", MUSHROOM_FARM, "mf89", TWENTY, sep=""),
    "dev90/lock_keepers_cottages": _set("dev90/lock_keepers_cottages.jsonl", LOCK_KEEPERS_COTTAGES, "lk90", TWENTY, sep=""),
    "dev90/hospice_grounds": _set("dev90/hospice_grounds.jsonl", HOSPICE_GROUNDS, "hg90", TWENTY, sep=""),
    "dev90/fairground_pier": _set("dev90/fairground_pier.jsonl", FAIRGROUND_PIER, "fp90", TWENTY, sep=""),
    "dev90/monastery_vineyard": _set("dev90/monastery_vineyard.jsonl", MONASTERY_VINEYARD, "mv90", TWENTY, sep=""),
    "dev91/ski_jump_centre": _set("dev91/ski_jump_centre.jsonl", SKI_JUMP_CENTRE, "sj91", TWENTY, sep=""),
    "dev91/sailing_centre": _set("dev91/sailing_centre.jsonl", SAILING_CENTRE, "sc91", TWENTY, sep=""),
    "dev91/aviation_museum": _set("dev91/aviation_museum.jsonl", AVIATION_MUSEUM, "am91", TWENTY, sep=""),
    "dev91/oyster_fishery": _set("dev91/oyster_fishery.jsonl", OYSTER_FISHERY, "of91", TWENTY, sep=""),
    "dev92/opal_mining_outpost": _set("dev92/opal_mining_outpost.jsonl", OPAL_MINING_OUTPOST, "om92", TWENTY, sep=""),
    "dev92/rice_terrace_village": _set("dev92/rice_terrace_village.jsonl", RICE_TERRACE_VILLAGE, "rt92", TWENTY, sep=""),
    "dev92/fireworks_factory": _set("dev92/fireworks_factory.jsonl", FIREWORKS_FACTORY, "ff92", TWENTY, sep=""),
    "dev92/vertical_farm": _set("dev92/vertical_farm.jsonl", VERTICAL_FARM, "vf92", TWENTY, sep=""),
    "dev93/salmon_cannery": _set("dev93/salmon_cannery.jsonl", SALMON_CANNERY, "sa93", TWENTY, sep=""),
    "dev93/cranberry_bog": _set("dev93/cranberry_bog.jsonl", CRANBERRY_BOG, "cb93", TWENTY, sep=""),
    "dev93/radio_telescope_array": _set("dev93/radio_telescope_array.jsonl", RADIO_TELESCOPE_ARRAY, "rt93", TWENTY,
                                        sep=""),
    "dev93/desert_research_station": _set("dev93/desert_research_station.jsonl", DESERT_RESEARCH_STATION, "dr93",
                                          TWENTY, sep=""),
    "dev94/lavender_distillery": _set("dev94/lavender_distillery.jsonl", LAVENDER_DISTILLERY, "lv94", TWENTY, sep=""),
    "dev94/ice_hotel": _set("dev94/ice_hotel.jsonl", ICE_HOTEL, "ih94", TWENTY, sep=""),
    "dev94/tidal_barrage": _set("dev94/tidal_barrage.jsonl", TIDAL_BARRAGE, "tb94", TWENTY, sep=""),
    "dev94/glassworks_town": _set("dev94/glassworks_town.jsonl", GLASSWORKS_TOWN, "gw94", TWENTY, sep=""),
    "dev95/chocolate_factory_town": _set("dev95/chocolate_factory_town.jsonl", CHOCOLATE_FACTORY_TOWN, "cf95", TWENTY,
                                         sep=""),
    "dev95/seaweed_coast": _set("dev95/seaweed_coast.jsonl", SEAWEED_COAST, "sw95", TWENTY, sep=""),
    "dev95/bell_foundry_village": _set("dev95/bell_foundry_village.jsonl", BELL_FOUNDRY_VILLAGE, "bf95", TWENTY, sep=""),
    "dev95/scout_jamboree": _set("dev95/scout_jamboree.jsonl", SCOUT_JAMBOREE, "sj95", TWENTY, sep=""),
    "dev96/geothermal_field": _set("dev96/geothermal_field.jsonl", GEOTHERMAL_FIELD, "gf96", TWENTY, sep=""),
    "dev96/seal_sanctuary": _set("dev96/seal_sanctuary.jsonl", SEAL_SANCTUARY, "ss96", TWENTY, sep=""),
    "dev96/cider_mill_farm": _set("dev96/cider_mill_farm.jsonl", CIDER_MILL_FARM, "cm96", TWENTY, sep=""),
    "dev96/motocross_track": _set("dev96/motocross_track.jsonl", MOTOCROSS_TRACK, "mx96", TWENTY, sep=""),
    "dev97/olive_terraces": _set("dev97/olive_terraces.jsonl", OLIVE_TERRACES, "ot97", TWENTY, sep=""),
    "dev97/sulphur_mine": _set("dev97/sulphur_mine.jsonl", SULPHUR_MINE, "su97", TWENTY, sep=""),
    "dev97/lifeboat_station": _set("dev97/lifeboat_station.jsonl", LIFEBOAT_STATION, "lb97", TWENTY, sep=""),
    "dev97/apiary_village": _set("dev97/apiary_village.jsonl", APIARY_VILLAGE, "ap97", TWENTY, sep=""),
    "dev98/expo_site": _set("dev98/expo_site.jsonl", EXPO_SITE, "ex98", TWENTY, sep=""),
    "dev98/salt_flats_speedway": _set("dev98/salt_flats_speedway.jsonl", SALT_FLATS_SPEEDWAY, "sf98", TWENTY, sep=""),
    "dev98/lido_park": _set("dev98/lido_park.jsonl", LIDO_PARK, "lp98", TWENTY, sep=""),
    "dev98/bamboo_temple": _set("dev98/bamboo_temple.jsonl", BAMBOO_TEMPLE, "bt98", TWENTY, sep=""),
    "dev99/market_square": _set("dev99/market_square.jsonl", MARKET_SQUARE, "ms99", TWENTY, sep=""),
    "dev99/riverbend": _set("dev99/riverbend.jsonl", RIVERBEND, "rb99", TWENTY, sep=""),
    "dev99/market_square_b": _set("dev99/market_square_b.jsonl", MARKET_SQUARE, "mb99", TWENTY, sep=""),
    "dev100/pithead_village": _set("dev100/pithead_village.jsonl", PITHEAD_VILLAGE, "ph100", TWENTY, sep=""),
    "dev100/regatta_course": _set("dev100/regatta_course.jsonl", REGATTA_COURSE, "rg100", TWENTY, sep=""),
    "dev100/dairy_farm": _set("dev100/dairy_farm.jsonl", DAIRY_FARM, "dy100", TWENTY, sep=""),
    "dev100/balloon_fiesta": _set("dev100/balloon_fiesta.jsonl", BALLOON_FIESTA, "hb100", TWENTY, sep=""),
    "dev101/rope_walk_quay": _set("dev101/rope_walk_quay.jsonl", ROPE_WALK_QUAY, "rw101", TWENTY, sep=""),
    "dev101/tulip_fields": _set("dev101/tulip_fields.jsonl", TULIP_FIELDS, "tf101", TWENTY, sep=""),
    "dev101/oasis_town": _set("dev101/oasis_town.jsonl", OASIS_TOWN, "oa101", TWENTY, sep=""),
    "dev101/avalanche_hamlet": _set("dev101/avalanche_hamlet.jsonl", AVALANCHE_HAMLET, "ah101", TWENTY, sep=""),
    "dev102/maple_sugar_bush": _set("dev102/maple_sugar_bush.jsonl", MAPLE_SUGAR_BUSH, "mb102", TWENTY, sep=""),
    "dev102/galvanising_works": _set("dev102/galvanising_works.jsonl", GALVANISING_WORKS, "gw102", TWENTY, sep=""),
    "dev102/show_caverns": _set("dev102/show_caverns.jsonl", SHOW_CAVERNS, "sc102", TWENTY, sep=""),
    "dev102/floating_market": _set("dev102/floating_market.jsonl", FLOATING_MARKET, "fm102", TWENTY, sep=""),
    "dev103/oast_valley": _set("dev103/oast_valley.jsonl", OAST_VALLEY, "ov103", TWENTY, sep=""),
    "dev103/bridge_works": _set("dev103/bridge_works.jsonl", BRIDGE_WORKS, "bw103", TWENTY, sep=""),
    "dev103/pine_campground": _set("dev103/pine_campground.jsonl", PINE_CAMPGROUND, "pc103", TWENTY, sep=""),
    "dev103/gannet_isle": _set("dev103/gannet_isle.jsonl", GANNET_ISLE, "gi103", TWENTY, sep=""),
    "dev104/rubber_plantation": _set("dev104/rubber_plantation.jsonl", RUBBER_PLANTATION, "rp104", TWENTY, sep=""),
    "dev104/fjord_ferry_village": _set("dev104/fjord_ferry_village.jsonl", FJORD_FERRY_VILLAGE, "ff104", TWENTY, sep=""),
    "dev104/silk_farm_village": _set("dev104/silk_farm_village.jsonl", SILK_FARM_VILLAGE, "sf104", TWENTY, sep=""),
    "dev104/medieval_tournament": _set("dev104/medieval_tournament.jsonl", MEDIEVAL_TOURNAMENT, "mt104", TWENTY, sep=""),
    "dev105/bauxite_mine_port": _set("dev105/bauxite_mine_port.jsonl", BAUXITE_MINE_PORT, "bp105", TWENTY, sep=""),
    "dev105/coffee_finca": _set("dev105/coffee_finca.jsonl", COFFEE_FINCA, "cf105", TWENTY, sep=""),
    "dev105/ice_road_camp": _set("dev105/ice_road_camp.jsonl", ICE_ROAD_CAMP, "ir105", TWENTY, sep=""),
    "dev105/canyon_rafting_base": _set("dev105/canyon_rafting_base.jsonl", CANYON_RAFTING_BASE, "cr105", TWENTY, sep=""),
    "dev106/peat_railway_bog": _set("dev106/peat_railway_bog.jsonl", PEAT_RAILWAY_BOG, "pb106", TWENTY, sep=""),
    "dev106/marble_quarry_town": _set("dev106/marble_quarry_town.jsonl", MARBLE_QUARRY_TOWN, "mq106", TWENTY, sep=""),
    "dev106/cruise_terminal": _set("dev106/cruise_terminal.jsonl", CRUISE_TERMINAL, "ct106", TWENTY, sep=""),
    "dev106/reindeer_herders_camp": _set("dev106/reindeer_herders_camp.jsonl", REINDEER_HERDERS_CAMP, "rh106", TWENTY, sep=""),
    "dev107/printing_works": _set("dev107/printing_works.jsonl", PRINTING_WORKS, "pw107", TWENTY, sep=""),
    "dev107/cheese_caves_village": _set("dev107/cheese_caves_village.jsonl", CHEESE_CAVES_VILLAGE, "cc107", TWENTY, sep=""),
    "dev107/solar_farm_substation": _set("dev107/solar_farm_substation.jsonl", SOLAR_FARM_SUBSTATION, "sf107", TWENTY, sep=""),
    "dev107/shearing_station": _set("dev107/shearing_station.jsonl", SHEARING_STATION, "ss107", TWENTY, sep=""),
    "dev108/canal_boatyard": _set("dev108/canal_boatyard.jsonl", CANAL_BOATYARD, "cb108", TWENTY, sep=""),
    "dev108/transmitter_station": _set("dev108/transmitter_station.jsonl", TRANSMITTER_STATION, "ts108", TWENTY, sep=""),
    "dev108/gold_dredge_camp": _set("dev108/gold_dredge_camp.jsonl", GOLD_DREDGE_CAMP, "gd108", TWENTY, sep=""),
    "dev108/caravanserai_oasis": _set("dev108/caravanserai_oasis.jsonl", CARAVANSERAI_OASIS, "co108", TWENTY, sep=""),
    "dev109/airship_hangar": _set("dev109/airship_hangar.jsonl", AIRSHIP_HANGAR, "ah109", TWENTY, sep=""),
    "dev109/watchmaking_town": _set("dev109/watchmaking_town.jsonl", WATCHMAKING_TOWN, "wt109", TWENTY, sep=""),
    "dev109/rodeo_grounds": _set("dev109/rodeo_grounds.jsonl", RODEO_GROUNDS, "rg109", TWENTY, sep=""),
    "dev109/cork_oak_estate": _set("dev109/cork_oak_estate.jsonl", CORK_OAK_ESTATE, "co109", TWENTY, sep=""),
    "dev110/fish_auction_quay": _set("dev110/fish_auction_quay.jsonl", FISH_AUCTION_QUAY, "fa110", TWENTY, sep=""),
    "dev110/volcano_village": _set("dev110/volcano_village.jsonl", VOLCANO_VILLAGE, "vv110", TWENTY, sep=""),
    "dev110/cotton_gin_town": _set("dev110/cotton_gin_town.jsonl", COTTON_GIN_TOWN, "cg110", TWENTY, sep=""),
    "dev110/boat_lift": _set("dev110/boat_lift.jsonl", BOAT_LIFT, "bl110", TWENTY, sep=""),
    "dev111/sled_dog_kennels": _set("dev111/sled_dog_kennels.jsonl", SLED_DOG_KENNELS, "sk111", TWENTY, sep=""),
    "dev111/windmill_village": _set("dev111/windmill_village.jsonl", WINDMILL_VILLAGE, "wv111", TWENTY, sep=""),
    "dev111/victorian_pumping_station": _set("dev111/victorian_pumping_station.jsonl", VICTORIAN_PUMPING_STATION, "vp111", TWENTY, sep=""),
    "dev111/zipline_park": _set("dev111/zipline_park.jsonl", ZIPLINE_PARK, "zp111", TWENTY, sep=""),
    "dev112/hop_kiln_farm_museum": _set("dev112/hop_kiln_farm_museum.jsonl", HOP_KILN_FARM_MUSEUM, "hk112", TWENTY, sep=""),
    "dev112/tide_mill_quay": _set("dev112/tide_mill_quay.jsonl", TIDE_MILL_QUAY, "tm112", TWENTY, sep=""),
    "dev112/ropeway_mine_camp": _set("dev112/ropeway_mine_camp.jsonl", ROPEWAY_MINE_CAMP, "rm112", TWENTY, sep=""),
    "dev112/sea_bathing_pool": _set("dev112/sea_bathing_pool.jsonl", SEA_BATHING_POOL, "sb112", TWENTY, sep=""),
    "dev113/seaplane_base": _set("dev113/seaplane_base.jsonl", SEAPLANE_BASE, "sp113", TWENTY, sep=""),
    "dev113/salt_mine_museum": _set("dev113/salt_mine_museum.jsonl", SALT_MINE_MUSEUM, "sm113", TWENTY, sep=""),
    "dev113/cricket_ground_village": _set("dev113/cricket_ground_village.jsonl", CRICKET_GROUND_VILLAGE, "cr113", TWENTY, sep=""),
    "dev113/mussel_farm_bay": _set("dev113/mussel_farm_bay.jsonl", MUSSEL_FARM_BAY, "mf113", TWENTY, sep=""),
    "dev114/lumber_flume_valley": _set("dev114/lumber_flume_valley.jsonl", LUMBER_FLUME_VALLEY, "lf114", TWENTY, sep=""),
    "dev114/charcoal_burners_wood": _set("dev114/charcoal_burners_wood.jsonl", CHARCOAL_BURNERS_WOOD, "cb114", TWENTY, sep=""),
    "dev114/railway_roundhouse": _set("dev114/railway_roundhouse.jsonl", RAILWAY_ROUNDHOUSE, "rr114", TWENTY, sep=""),
    "dev114/banana_plantation": _set("dev114/banana_plantation.jsonl", BANANA_PLANTATION, "bp114", TWENTY, sep=""),
    "dev115/peat_cutting_moss": _set("dev115/peat_cutting_moss.jsonl", PEAT_CUTTING_MOSS, "pc115", TWENTY, sep=""),
    "dev115/lighthouse_causeway": _set("dev115/lighthouse_causeway.jsonl", LIGHTHOUSE_CAUSEWAY, "lc115", TWENTY, sep=""),
    "dev115/silk_road_caravan_market": _set("dev115/silk_road_caravan_market.jsonl", SILK_ROAD_CARAVAN_MARKET, "sr115", TWENTY, sep=""),
    "dev115/gravel_pit_nature_reserve": _set("dev115/gravel_pit_nature_reserve.jsonl", GRAVEL_PIT_NATURE_RESERVE, "gp115", TWENTY, sep=""),
    "dev116/hovercraft_terminal": _set("dev116/hovercraft_terminal.jsonl", HOVERCRAFT_TERMINAL, "ht116", TWENTY, sep=""),
    "dev116/stud_dairy_showground": _set("dev116/stud_dairy_showground.jsonl", STUD_DAIRY_SHOWGROUND, "sg116", TWENTY, sep=""),
    "dev116/copper_mine_tailings_dam": _set("dev116/copper_mine_tailings_dam.jsonl", COPPER_MINE_TAILINGS_DAM, "ct116", TWENTY, sep=""),
    "dev116/ferry_slipway_island": _set("dev116/ferry_slipway_island.jsonl", FERRY_SLIPWAY_ISLAND, "fi116", TWENTY, sep=""),
    "dev117/whaling_station_museum": _set("dev117/whaling_station_museum.jsonl", WHALING_STATION_MUSEUM, "wh117", TWENTY, sep=""),
    "dev117/sheepdog_trials_field": _set("dev117/sheepdog_trials_field.jsonl", SHEEPDOG_TRIALS_FIELD, "sd117", TWENTY, sep=""),
    "dev117/tunnel_boring_worksite": _set("dev117/tunnel_boring_worksite.jsonl", TUNNEL_BORING_WORKSITE, "tb117", TWENTY, sep=""),
    "dev117/indoor_market_hall": _set("dev117/indoor_market_hall.jsonl", INDOOR_MARKET_HALL, "mh117", TWENTY, sep=""),
    "dev118/wildfire_base_camp": _set("dev118/wildfire_base_camp.jsonl", WILDFIRE_BASE_CAMP, "wf118", TWENTY, sep=""),
    "dev118/glider_airfield": _set("dev118/glider_airfield.jsonl", GLIDER_AIRFIELD, "gl118", TWENTY, sep=""),
    "dev118/citrus_packing_house": _set("dev118/citrus_packing_house.jsonl", CITRUS_PACKING_HOUSE, "cp118", TWENTY, sep=""),
    "dev118/stone_circle_heritage_site": _set("dev118/stone_circle_heritage_site.jsonl", STONE_CIRCLE_HERITAGE_SITE, "sc118", TWENTY, sep=""),
    "dev119/wetland_boardwalk_reserve": _set("dev119/wetland_boardwalk_reserve.jsonl", WETLAND_BOARDWALK_RESERVE, "wb119", TWENTY, sep=""),
    "dev119/maglev_test_track": _set("dev119/maglev_test_track.jsonl", MAGLEV_TEST_TRACK, "mg119", TWENTY, sep=""),
    "dev119/skate_park_plaza": _set("dev119/skate_park_plaza.jsonl", SKATE_PARK_PLAZA, "sk119", TWENTY, sep=""),
    "dev119/iron_ore_railhead": _set("dev119/iron_ore_railhead.jsonl", IRON_ORE_RAILHEAD, "io119", TWENTY, sep=""),
    "dev120/bonfire_night_common": _set("dev120/bonfire_night_common.jsonl", BONFIRE_NIGHT_COMMON, "bn120", TWENTY, sep=""),
    "dev120/pumice_quarry_island": _set("dev120/pumice_quarry_island.jsonl", PUMICE_QUARRY_ISLAND, "pq120", TWENTY, sep=""),
    "dev120/greyhound_stadium": _set("dev120/greyhound_stadium.jsonl", GREYHOUND_STADIUM, "gs120", TWENTY, sep=""),
    "dev120/music_conservatory": _set("dev120/music_conservatory.jsonl", MUSIC_CONSERVATORY, "mc120", TWENTY, sep=""),
    "dev121/velodrome_track_centre": _set("dev121/velodrome_track_centre.jsonl", VELODROME_TRACK_CENTRE, "vd121", TWENTY, sep=""),
    "dev121/polo_club_ground": _set("dev121/polo_club_ground.jsonl", POLO_CLUB_GROUND, "pc121", TWENTY, sep=""),
    "dev121/rum_distillery_estate": _set("dev121/rum_distillery_estate.jsonl", RUM_DISTILLERY_ESTATE, "rd121", TWENTY, sep=""),
    "dev121/geyser_basin_park": _set("dev121/geyser_basin_park.jsonl", GEYSER_BASIN_PARK, "gb121", TWENTY, sep=""),
    "dev122/flower_auction_hall": _set("dev122/flower_auction_hall.jsonl", FLOWER_AUCTION_HALL, "fa122", TWENTY, sep=""),
    "dev122/polar_research_station": _set("dev122/polar_research_station.jsonl", POLAR_RESEARCH_STATION, "pr122", TWENTY, sep=""),
    "dev122/truffle_oak_plantation": _set("dev122/truffle_oak_plantation.jsonl", TRUFFLE_OAK_PLANTATION, "to122", TWENTY, sep=""),
    "dev122/cocoa_fermentary_cooperative": _set("dev122/cocoa_fermentary_cooperative.jsonl", COCOA_FERMENTARY_COOPERATIVE, "cf122", TWENTY, sep=""),
    "dev123/onsen_hot_spring_town": _set("dev123/onsen_hot_spring_town.jsonl", ONSEN_HOT_SPRING_TOWN, "os123", TWENTY, sep=""),
    "dev123/sand_dune_buggy_park": _set("dev123/sand_dune_buggy_park.jsonl", SAND_DUNE_BUGGY_PARK, "db123", TWENTY, sep=""),
    "dev123/cattle_feedlot": _set("dev123/cattle_feedlot.jsonl", CATTLE_FEEDLOT, "cl123", TWENTY, sep=""),
    "dev123/postal_sorting_centre": _set("dev123/postal_sorting_centre.jsonl", POSTAL_SORTING_CENTRE, "ps123", TWENTY, sep=""),
    "dev124/offshore_wind_service_port": _set("dev124/offshore_wind_service_port.jsonl", OFFSHORE_WIND_SERVICE_PORT, "ow124", TWENTY, sep=""),
    "dev124/monorail_theme_resort": _set("dev124/monorail_theme_resort.jsonl", MONORAIL_THEME_RESORT, "mr124", TWENTY, sep=""),
    "dev124/waste_incinerator_plant": _set("dev124/waste_incinerator_plant.jsonl", WASTE_INCINERATOR_PLANT, "wi124", TWENTY, sep=""),
    "dev124/carnival_parade_route": _set("dev124/carnival_parade_route.jsonl", CARNIVAL_PARADE_ROUTE, "cv124", TWENTY, sep=""),
    "dev125/royal_mint_coin_works": _set("dev125/royal_mint_coin_works.jsonl", ROYAL_MINT_COIN_WORKS, "rm125", TWENTY, sep=""),
    "dev125/bobsleigh_track_venue": _set("dev125/bobsleigh_track_venue.jsonl", BOBSLEIGH_TRACK_VENUE, "bs125", TWENTY, sep=""),
    "dev125/shipbreaking_beach_yard": _set("dev125/shipbreaking_beach_yard.jsonl", SHIPBREAKING_BEACH_YARD, "sb125", TWENTY, sep=""),
    "dev125/lng_import_terminal": _set("dev125/lng_import_terminal.jsonl", LNG_IMPORT_TERMINAL, "lg125", TWENTY, sep=""),
    "dev126/sculpture_park_estate": _set("dev126/sculpture_park_estate.jsonl", SCULPTURE_PARK_ESTATE, "sp126", TWENTY, sep=""),
    "dev126/biogas_farm_digester": _set("dev126/biogas_farm_digester.jsonl", BIOGAS_FARM_DIGESTER, "bg126", TWENTY, sep=""),
    "dev126/bazaar_old_city_souk": _set("dev126/bazaar_old_city_souk.jsonl", BAZAAR_OLD_CITY_SOUK, "bz126", TWENTY, sep=""),
    "dev126/rowing_lake_regatta_centre": _set("dev126/rowing_lake_regatta_centre.jsonl", ROWING_LAKE_REGATTA_CENTRE, "rl126", TWENTY, sep=""),
    "dev127/alpaca_trekking_farm": _set("dev127/alpaca_trekking_farm.jsonl", ALPACA_TREKKING_FARM, "al127", TWENTY, sep=""),
    "dev127/pipe_organ_concert_hall": _set("dev127/pipe_organ_concert_hall.jsonl", PIPE_ORGAN_CONCERT_HALL, "oh127", TWENTY, sep=""),
    "dev127/highrise_construction_site": _set("dev127/highrise_construction_site.jsonl", HIGHRISE_CONSTRUCTION_SITE, "hc127", TWENTY, sep=""),
    "dev127/mangrove_eco_lodge": _set("dev127/mangrove_eco_lodge.jsonl", MANGROVE_ECO_LODGE, "me127", TWENTY, sep=""),
    "dev128/fibre_cable_factory": _set("dev128/fibre_cable_factory.jsonl", FIBRE_CABLE_FACTORY, "fc128", TWENTY, sep=""),
    "dev128/equestrian_eventing_course": _set("dev128/equestrian_eventing_course.jsonl", EQUESTRIAN_EVENTING_COURSE, "ev128", TWENTY, sep=""),
    "dev128/paragliding_launch_hill": _set("dev128/paragliding_launch_hill.jsonl", PARAGLIDING_LAUNCH_HILL, "pg128", TWENTY, sep=""),
    "dev128/drinking_water_treatment_works": _set("dev128/drinking_water_treatment_works.jsonl", DRINKING_WATER_TREATMENT_WORKS, "dw128", TWENTY, sep=""),
    "dev129/river_cruise_ship": _set("dev129/river_cruise_ship.jsonl", RIVER_CRUISE_SHIP, "rc129", TWENTY, sep=""),
    "dev129/sea_cliff_climbing_crag": _set("dev129/sea_cliff_climbing_crag.jsonl", SEA_CLIFF_CLIMBING_CRAG, "cc129", TWENTY, sep=""),
    "dev129/pharmaceutical_plant": _set("dev129/pharmaceutical_plant.jsonl", PHARMACEUTICAL_PLANT, "ph129", TWENTY, sep=""),
    "dev129/rural_wedding_venue": _set("dev129/rural_wedding_venue.jsonl", RURAL_WEDDING_VENUE, "wv129", TWENTY, sep=""),
    "dev130/wildlife_rescue_hospital": _set("dev130/wildlife_rescue_hospital.jsonl", WILDLIFE_RESCUE_HOSPITAL, "wr130", TWENTY, sep=""),
    "dev130/airport_cargo_centre": _set("dev130/airport_cargo_centre.jsonl", AIRPORT_CARGO_CENTRE, "ac130", TWENTY, sep=""),
    "dev130/coral_island_dive_resort": _set("dev130/coral_island_dive_resort.jsonl", CORAL_ISLAND_DIVE_RESORT, "dr130", TWENTY, sep=""),
    "dev130/meat_processing_abattoir": _set("dev130/meat_processing_abattoir.jsonl", MEAT_PROCESSING_ABATTOIR, "ab130", TWENTY, sep=""),
    "dev131/ice_fishing_lake_camp": _set("dev131/ice_fishing_lake_camp.jsonl", ICE_FISHING_LAKE_CAMP, "if131", TWENTY, sep=""),
    "dev131/cinema_multiplex": _set("dev131/cinema_multiplex.jsonl", CINEMA_MULTIPLEX, "cm131", TWENTY, sep=""),
    "dev131/hydrogen_fuel_depot": _set("dev131/hydrogen_fuel_depot.jsonl", HYDROGEN_FUEL_DEPOT, "hf131", TWENTY, sep=""),
    "dev131/open_pit_diamond_mine": _set("dev131/open_pit_diamond_mine.jsonl", OPEN_PIT_DIAMOND_MINE, "dm131", TWENTY, sep=""),
    "dev132/tobacco_curing_barns": _set("dev132/tobacco_curing_barns.jsonl", TOBACCO_CURING_BARNS, "tb132", TWENTY, sep=""),
    "dev132/adventure_playground": _set("dev132/adventure_playground.jsonl", ADVENTURE_PLAYGROUND, "ap132", TWENTY, sep=""),
    "dev132/floating_solar_reservoir": _set("dev132/floating_solar_reservoir.jsonl", FLOATING_SOLAR_RESERVOIR, "fs132", TWENTY, sep=""),
    "dev132/civic_courthouse_square": _set("dev132/civic_courthouse_square.jsonl", CIVIC_COURTHOUSE_SQUARE, "cs132", TWENTY, sep=""),
    "dev133/aircraft_carrier_deck": _set("dev133/aircraft_carrier_deck.jsonl", AIRCRAFT_CARRIER_DECK, "cv133", TWENTY, sep=""),
    "dev133/solar_tower_power_plant": _set("dev133/solar_tower_power_plant.jsonl", SOLAR_TOWER_POWER_PLANT, "st133", TWENTY, sep=""),
    "dev133/rooftop_garden_block": _set("dev133/rooftop_garden_block.jsonl", ROOFTOP_GARDEN_BLOCK, "rg133", TWENTY, sep=""),
    "dev133/truck_stop_weigh_station": _set("dev133/truck_stop_weigh_station.jsonl", TRUCK_STOP_WEIGH_STATION, "ts133", TWENTY, sep=""),
    "dev134/scrap_metal_yard": _set("dev134/scrap_metal_yard.jsonl", SCRAP_METAL_YARD, "sm134", TWENTY, sep=""),
    "dev134/treetop_canopy_walkway": _set("dev134/treetop_canopy_walkway.jsonl", TREETOP_CANOPY_WALKWAY, "tw134", TWENTY, sep=""),
    "dev134/highland_games_field": _set("dev134/highland_games_field.jsonl", HIGHLAND_GAMES_FIELD, "hg134", TWENTY, sep=""),
    "dev134/dinosaur_fossil_dig_site": _set("dev134/dinosaur_fossil_dig_site.jsonl", DINOSAUR_FOSSIL_DIG_SITE, "fd134", TWENTY, sep=""),
    "dev135/roman_amphitheatre_opera": _set("dev135/roman_amphitheatre_opera.jsonl", ROMAN_AMPHITHEATRE_OPERA, "ra135", TWENTY, sep=""),
    "dev135/high_speed_rail_station": _set("dev135/high_speed_rail_station.jsonl", HIGH_SPEED_RAIL_STATION, "hs135", TWENTY, sep=""),
    "dev135/rice_mill_cooperative": _set("dev135/rice_mill_cooperative.jsonl", RICE_MILL_COOPERATIVE, "rm135", TWENTY, sep=""),
    "dev135/surf_beach_lifeguard_club": _set("dev135/surf_beach_lifeguard_club.jsonl", SURF_BEACH_LIFEGUARD_CLUB, "sb135", TWENTY, sep=""),
    "dev136/west_end_theatre_backstage": _set("dev136/west_end_theatre_backstage.jsonl", WEST_END_THEATRE_BACKSTAGE, "wt136", TWENTY, sep=""),
    "dev136/coastal_radar_station": _set("dev136/coastal_radar_station.jsonl", COASTAL_RADAR_STATION, "cr136", TWENTY, sep=""),
    "dev136/car_boot_sale_field": _set("dev136/car_boot_sale_field.jsonl", CAR_BOOT_SALE_FIELD, "cb136", TWENTY, sep=""),
    "dev136/bamboo_raft_river_village": _set("dev136/bamboo_raft_river_village.jsonl", BAMBOO_RAFT_RIVER_VILLAGE, "br136", TWENTY, sep=""),
    "dev137/ship_canal_swing_bridge": _set("dev137/ship_canal_swing_bridge.jsonl", SHIP_CANAL_SWING_BRIDGE, "sw137", TWENTY, sep=""),
    "dev137/go_kart_track": _set("dev137/go_kart_track.jsonl", GO_KART_TRACK, "gk137", TWENTY, sep=""),
    "dev137/quarantine_station_island": _set("dev137/quarantine_station_island.jsonl", QUARANTINE_STATION_ISLAND, "qi137", TWENTY, sep=""),
    "dev137/ice_cream_factory": _set("dev137/ice_cream_factory.jsonl", ICE_CREAM_FACTORY, "ic137", TWENTY, sep=""),
    "dev138/cemetery_crematorium_grounds": _set("dev138/cemetery_crematorium_grounds.jsonl", CEMETERY_CREMATORIUM_GROUNDS, "cg138", TWENTY, sep=""),
    "dev138/pearl_farm_lagoon": _set("dev138/pearl_farm_lagoon.jsonl", PEARL_FARM_LAGOON, "pf138", TWENTY, sep=""),
    "dev138/market_garden_smallholding": _set("dev138/market_garden_smallholding.jsonl", MARKET_GARDEN_SMALLHOLDING, "mg138", TWENTY, sep=""),
    "dev138/motorway_bridge_roadworks": _set("dev138/motorway_bridge_roadworks.jsonl", MOTORWAY_BRIDGE_ROADWORKS, "mb138", TWENTY, sep=""),
    "dev139/ferris_wheel_embankment": _set("dev139/ferris_wheel_embankment.jsonl", FERRIS_WHEEL_EMBANKMENT, "fw139", TWENTY, sep=""),
    "dev139/pea_vining_station": _set("dev139/pea_vining_station.jsonl", PEA_VINING_STATION, "pv139", TWENTY, sep=""),
    "dev139/alpine_dairy_pasture": _set("dev139/alpine_dairy_pasture.jsonl", ALPINE_DAIRY_PASTURE, "ad139", TWENTY, sep=""),
    "dev139/dry_ski_slope_centre": _set("dev139/dry_ski_slope_centre.jsonl", DRY_SKI_SLOPE_CENTRE, "ds139", TWENTY, sep=""),
    "dev140/village_fete_green": _set("dev140/village_fete_green.jsonl", VILLAGE_FETE_GREEN, "vf140", TWENTY, sep=""),
    "dev140/pumped_storage_cavern": _set("dev140/pumped_storage_cavern.jsonl", PUMPED_STORAGE_CAVERN, "ps140", TWENTY, sep=""),
    "dev140/ferry_bridge_toll_plaza": _set("dev140/ferry_bridge_toll_plaza.jsonl", FERRY_BRIDGE_TOLL_PLAZA, "ft140", TWENTY, sep=""),
    "dev140/national_archives_repository": _set("dev140/national_archives_repository.jsonl", NATIONAL_ARCHIVES_REPOSITORY, "na140", TWENTY, sep=""),
    "dev141/ostrich_farm_visitor_park": _set("dev141/ostrich_farm_visitor_park.jsonl", OSTRICH_FARM_VISITOR_PARK, "of141", TWENTY, sep=""),
    "dev141/floating_dry_dock_yard": _set("dev141/floating_dry_dock_yard.jsonl", FLOATING_DRY_DOCK_YARD, "fd141", TWENTY, sep=""),
    "dev141/research_reactor_campus": _set("dev141/research_reactor_campus.jsonl", RESEARCH_REACTOR_CAMPUS, "rr141", TWENTY, sep=""),
    "dev141/maize_maze_farm_shop": _set("dev141/maize_maze_farm_shop.jsonl", MAIZE_MAZE_FARM_SHOP, "mm141", TWENTY, sep=""),
    "dev142/drive_in_cinema_lot": _set("dev142/drive_in_cinema_lot.jsonl", DRIVE_IN_CINEMA_LOT, "dc142", TWENTY, sep=""),
    "dev142/estuary_cockle_beds": _set("dev142/estuary_cockle_beds.jsonl", ESTUARY_COCKLE_BEDS, "ec142", TWENTY, sep=""),
    "dev142/tennis_championship_grounds": _set("dev142/tennis_championship_grounds.jsonl", TENNIS_CHAMPIONSHIP_GROUNDS, "tc142", TWENTY, sep=""),
    "dev142/kasbah_mountain_village": _set("dev142/kasbah_mountain_village.jsonl", KASBAH_MOUNTAIN_VILLAGE, "kv142", TWENTY, sep=""),
    "dev143/lighthouse_keepers_island": _set("dev143/lighthouse_keepers_island.jsonl", LIGHTHOUSE_KEEPERS_ISLAND, "lk143", TWENTY, sep=""),
    "dev143/brass_band_contest_hall": _set("dev143/brass_band_contest_hall.jsonl", BRASS_BAND_CONTEST_HALL, "bb143", TWENTY, sep=""),
    "dev143/canal_lift_bridge_village": _set("dev143/canal_lift_bridge_village.jsonl", CANAL_LIFT_BRIDGE_VILLAGE, "cl143", TWENTY, sep=""),
    "dev143/hill_fort_archaeology_camp": _set("dev143/hill_fort_archaeology_camp.jsonl", HILL_FORT_ARCHAEOLOGY_CAMP, "ha143", TWENTY, sep=""),
    "dev144/seaside_crazy_golf_front": _set("dev144/seaside_crazy_golf_front.jsonl", SEASIDE_CRAZY_GOLF_FRONT, "sg144", TWENTY, sep=""),
    "dev144/sugar_beet_factory_campaign": _set("dev144/sugar_beet_factory_campaign.jsonl", SUGAR_BEET_FACTORY_CAMPAIGN, "sb144", TWENTY, sep=""),
    "dev144/mountain_bike_race_village": _set("dev144/mountain_bike_race_village.jsonl", MOUNTAIN_BIKE_RACE_VILLAGE, "mb144", TWENTY, sep=""),
    "dev144/city_library_and_archive": _set("dev144/city_library_and_archive.jsonl", CITY_LIBRARY_AND_ARCHIVE, "cy144", TWENTY, sep=""),
}


def _rows(name: str) -> list[dict]:
    rows = []
    text = SETS[name]["file"].read_text(encoding="utf-8")
    for i, line in enumerate(text.splitlines(), 1):
        assert line.strip(), f"{name} line {i}: blank line"
        rows.append(json.loads(line))
    return rows


def _kb(name: str) -> tuple[set[str], set[str]]:
    kb = SETS[name]["kb"]
    space = yaml.safe_load((kb / "information_space.yaml").read_text(encoding="utf-8"))
    world = yaml.safe_load((kb / "map.yaml").read_text(encoding="utf-8"))
    return {lm["name"] for lm in world["landmarks"]}, {c["name"] for c in space["categories"]}


@pytest.mark.parametrize("name", sorted(SETS))
def test_rows_are_well_formed(name: str) -> None:
    for row in _rows(name):
        assert set(row) >= {"id", "regime", "report", "expected"}, row
        assert row["regime"] in SETS[name]["prefixes"], row["id"]
        assert row.get("source", "hand") == "hand", row["id"]
        assert isinstance(row["report"], str) and row["report"].strip(), row["id"]
        assert isinstance(row["expected"], list), row["id"]
        for item in row["expected"]:
            assert set(item) == {"location", "category"}, row["id"]
        pairs = [(e["location"], e["category"]) for e in row["expected"]]
        assert len(pairs) == len(set(pairs)), f"{row['id']}: duplicate expected pair"


@pytest.mark.parametrize("name", sorted(SETS))
def test_ids_unique_and_prefixed(name: str) -> None:
    rows = _rows(name)
    ids = [r["id"] for r in rows]
    assert len(ids) == len(set(ids)), [i for i, n in Counter(ids).items() if n > 1]
    for row in rows:
        prefix = SETS[name]["prefixes"][row["regime"]]
        assert row["id"].startswith(prefix), row["id"]
        assert row["id"][len(prefix) :].isdigit(), row["id"]


def test_ids_unique_across_files() -> None:
    ids = [r["id"] for name in SETS for r in _rows(name)]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize("name", sorted(SETS))
def test_labels_exist_in_kb(name: str) -> None:
    landmarks, categories = _kb(name)
    for row in _rows(name):
        for item in row["expected"]:
            assert item["location"] in landmarks, f"{row['id']}: {item['location']!r}"
            assert item["category"] in categories, f"{row['id']}: {item['category']!r}"


@pytest.mark.parametrize("name", sorted(SETS))
def test_counts_and_no_claim_share(name: str) -> None:
    rows = _rows(name)
    counts = SETS[name]["counts"]
    assert Counter(r["regime"] for r in rows) == counts
    for regime, n in counts.items():
        empty = sum(1 for r in rows if r["regime"] == regime and not r["expected"])
        # about 10% of every regime makes no groundable claim
        assert 0.05 * n <= empty <= 0.2 * n, (regime, empty)


@pytest.mark.parametrize("name", sorted(SETS))
def test_reports_are_distinct(name: str) -> None:
    reports = [r["report"].strip().lower() for r in _rows(name)]
    assert len(reports) == len(set(reports))

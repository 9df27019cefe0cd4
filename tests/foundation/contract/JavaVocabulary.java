/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rei.dsl.edit.EditOperation;
import org.rei.dsl.edit.server.Protocol;
import org.rei.maps.MapBlocks;
import org.rei.maps.OccupancyMap;
import org.rei.monitor.config.CaseReader;
import org.rei.monitor.config.MonitorSpec;
import org.rei.monitor.signals.Signal;
import org.rei.monitor.wamp.LiveMonitor;
import org.rei.sut.kit.SutClient;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.validation.VeplValidator;
import org.rei.warmjvm.CommandServer;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The Java copies of contract/vocabulary.json's facts, read from the built jars' constants and printed as JSON for
 * test_vocabulary_contract.py ({@code java -cp rei-monitor.jar:rei-sut-kit.jar:rei-room-editor.jar JavaVocabulary.java}).
 */
public final class JavaVocabulary {
	public static void main(String[] args) throws Exception {
		Map<String, Object> facts = new LinkedHashMap<>();
		facts.put("run_id_pattern", MonitorSpec.RUN_ID_PATTERN);
		facts.put("topic_template", MonitorSpec.TOPIC_TEMPLATE);
		facts.put("max_message_size", LiveMonitor.MAX_MESSAGE_SIZE);
		facts.put("sut_max_message_size", SutClient.MAX_MESSAGE_SIZE);
		facts.put("mission_events", MissionEvent.KINDS);
		facts.put("vepl_mission_events", VeplValidator.MISSION_EVENTS);
		facts.put("fault_events", MissionEvent.FAULT_EVENTS);
		facts.put("signal_record", Arrays.stream(Signal.class.getRecordComponents()).map(c -> c.getName()).toList());
		facts.put("signal_payload", List.copyOf(new Signal(0, 0, "S", "robot", "", 0).payload().keySet()));
		facts.put("sut_uri_template", SutClient.URI_TEMPLATE);
		facts.put("sut_from_simulation", SutClient.FROM_SIMULATION);
		facts.put("sut_from_sut", SutClient.FROM_SUT);
		facts.put("sut_drives", org.rei.sut.kit.Session.DRIVES);
		facts.put("sut_outline_types", org.rei.sut.kit.Session.Outline.TYPES);
		facts.put("sut_procedures", SutClient.PROCEDURES);
		facts.put("sut_environment", List.of(SutClient.ENV_ROUTER_URL, SutClient.ENV_REALM, SutClient.ENV_RUN_ID,
				SutClient.ENV_AUTH_FILE));
		facts.put("sut_case_dir", SutClient.ENV_CASE_DIR);
		facts.put("warm_jvm_request", CommandServer.REQUEST);
		facts.put("warm_jvm_answer", CommandServer.ANSWER);
		facts.put("room_editor_commands", Protocol.COMMANDS);
		facts.put("room_editor_error_kinds", Protocol.ERROR_KINDS);
		facts.put("room_editor_sides", Protocol.SIDES);
		Map<String, List<String>> operations = new LinkedHashMap<>();
		for (String op : Protocol.OPERATIONS) {
			Class<?> record = Class.forName(EditOperation.class.getName() + "$" + Character.toUpperCase(op.charAt(0))
					+ op.substring(1));
			operations.put(op, Arrays.stream(record.getRecordComponents()).map(c -> c.getName()).toList());
		}
		facts.put("room_editor_operations", operations);
		facts.put("room_editor_point", Arrays.stream(EditOperation.Waypoint.class.getRecordComponents())
				.map(c -> c.getName()).toList());
		facts.put("map_max_cells", OccupancyMap.MAX_CELLS); // the room editor's jar holds the language and its maps
		facts.put("map_max_blocks", MapBlocks.MAX_BLOCKS);
		facts.put("footprint_types", CaseReader.FOOTPRINT_TYPES);
		System.out.println(new ObjectMapper().writeValueAsString(facts));
	}
}

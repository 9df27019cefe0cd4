/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.sut.kit;

import java.net.URI;
import java.util.List;
import java.util.concurrent.ScheduledExecutorService;

import ws.wamp.jawampa.WampMessages.SubscribedMessage;
import ws.wamp.jawampa.WampMessages.WampMessage;
import ws.wamp.jawampa.WampSerialization;
import ws.wamp.jawampa.connection.IWampClientConnectionConfig;
import ws.wamp.jawampa.connection.IWampConnectionListener;
import ws.wamp.jawampa.connection.IWampConnector;
import ws.wamp.jawampa.connection.IWampConnectorProvider;
import ws.wamp.jawampa.transport.netty.NettyWampClientConnectorProvider;

/**
 * jawampa's netty transport that also tells when a subscription is really in place. jawampa queues every received
 * message as a task on its single-threaded loop and marks a subscription active in one more task queued while it
 * handles the router's SUBSCRIBED; an EVENT queued before that task is dropped. The SUT must call {@code hello}
 * (which starts the simulation) only after that, so {@code onSubscribed} runs on the loop behind both tasks: FIFO
 * order then guarantees the subscription is active.
 */
final class SubscribedSignal implements IWampConnectorProvider {

	private final NettyWampClientConnectorProvider netty = new NettyWampClientConnectorProvider();
	private final Runnable onSubscribed;

	SubscribedSignal(Runnable onSubscribed) {
		this.onSubscribed = onSubscribed;
	}

	@Override
	public ScheduledExecutorService createScheduler() {
		return netty.createScheduler();
	}

	@Override
	public IWampConnector createConnector(URI uri, IWampClientConnectionConfig configuration,
			List<WampSerialization> serializations) throws Exception {
		IWampConnector connector = netty.createConnector(uri, configuration, serializations);
		return (scheduler, connectListener, listener) -> connector.connect(scheduler, connectListener,
				new IWampConnectionListener() {
					@Override
					public void messageReceived(WampMessage message) {
						listener.messageReceived(message); // queues jawampa's task for the message
						if (message instanceof SubscribedMessage) {
							// runs after that task, which queued the activation: queue behind the activation
							scheduler.execute(() -> scheduler.execute(onSubscribed));
						}
					}

					@Override
					public void transportClosed() {
						listener.transportClosed();
					}

					@Override
					public void transportError(Throwable cause) {
						listener.transportError(cause);
					}
				});
	}
}

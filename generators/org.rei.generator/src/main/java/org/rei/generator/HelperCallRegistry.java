/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.generator;

import java.lang.reflect.Method;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.eclipse.epsilon.egl.output.IOutputBuffer;
import org.eclipse.epsilon.eol.dom.Expression;
import org.eclipse.epsilon.eol.execute.context.IEolContext;
import org.eclipse.epsilon.eol.execute.introspection.java.ObjectMethod;
import org.eclipse.epsilon.eol.execute.operations.contributors.OperationContributor;
import org.eclipse.epsilon.eol.execute.operations.contributors.OperationContributorRegistry;

/**
 * Remembers how template calls on {@link TemplateSupport} and on EGL's output buffer resolve; everything else is
 * looked up as before.
 * <p>
 * Why: EOL looks a Java method up anew on every call, asking every operation contributor and copying the target
 * class's method table each time (some 20 microseconds a call). Every {@code [%=...%]} is such a call on the output
 * buffer, and the templates make dozens per floor, so a 10,000-floor room spent over 10 s in method lookup alone.
 * Only these two kinds of target are cached: for them the answer depends on the class, the name and the argument
 * classes alone, never on the instance (no model owns them, no contributor is stateful for them).
 */
final class HelperCallRegistry extends OperationContributorRegistry {

	/** Target class, operation name, argument count and the classes of up to three arguments. */
	private record Key(Class<?> target, String name, int arity, Class<?> first, Class<?> second, Class<?> third) {

		static Key of(Object target, String name, Object[] arguments) {
			return new Key(target.getClass(), name, arguments.length, classOf(arguments, 0), classOf(arguments, 1),
					classOf(arguments, 2));
		}

		private static Class<?> classOf(Object[] arguments, int i) {
			return i >= arguments.length ? null : arguments[i] == null ? Void.class : arguments[i].getClass();
		}
	}

	private final OperationContributorRegistry delegate;
	private final Set<Key> noUnevaluated = new HashSet<>();
	private final Map<Key, Method> evaluated = new HashMap<>();

	HelperCallRegistry(OperationContributorRegistry delegate) {
		this.delegate = delegate;
	}

	private static boolean cacheable(Object target) {
		return target instanceof TemplateSupport || target instanceof IOutputBuffer;
	}

	@Override
	public ObjectMethod findContributedMethodForUnevaluatedParameters(Object target, String name,
			List<Expression> parameterExpressions, IEolContext context) {
		if (!cacheable(target)) {
			return delegate.findContributedMethodForUnevaluatedParameters(target, name, parameterExpressions, context);
		}
		Key key = new Key(target.getClass(), name, parameterExpressions.size(), null, null, null);
		if (noUnevaluated.contains(key)) {
			return null;
		}
		ObjectMethod method = delegate.findContributedMethodForUnevaluatedParameters(target, name, parameterExpressions,
				context);
		if (method == null) {
			noUnevaluated.add(key);
		}
		return method;
	}

	@Override
	public ObjectMethod findContributedMethodForEvaluatedParameters(Object target, String name, Object[] parameters,
			IEolContext context) {
		if (!cacheable(target) || parameters.length > 3) {
			return delegate.findContributedMethodForEvaluatedParameters(target, name, parameters, context);
		}
		Key key = Key.of(target, name, parameters);
		Method known = evaluated.get(key);
		if (known != null) {
			return new ObjectMethod(target, known);
		}
		ObjectMethod method = delegate.findContributedMethodForEvaluatedParameters(target, name, parameters, context);
		if (method != null && method.getObject() == target && method.getMethod() != null) {
			evaluated.put(key, method.getMethod()); // a plain Java method of the target itself
		}
		return method;
	}

	@Override
	public void add(OperationContributor operationContributor) {
		delegate.add(operationContributor);
	}

	@Override
	public Stream<OperationContributor> stream() {
		return delegate.stream();
	}
}

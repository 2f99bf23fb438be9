# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The Python front end: a walk of one module's syntax tree to its facts.

The analysed code is read with :mod:`ast` only: it is never imported or
executed. Names are resolved through the module's imports (``import rospy``,
``from rclpy.node import Node``, ``import rclpy.node as rn``, relative
imports, ``from X import *``) and, for the package's own modules
(``package_modules``), through their code, parsed the same way; a call
is recognised by the canonical name of what it calls, looked up in
:mod:`colcon_rsia.frontend.python_api`.

Ids (the same meaning as the C++ front end's USRs):

* functions: ``module:func``, ``module:Class.method``, nested functions
  ``module:outer.inner``; the module body is the function
  ``module:<module>``; lambdas ``lambda@<file>:<line>:<col>`` (named
  ``lambda@<file>:<line>``), ``<file>`` relative to the package;
* handles (the variable or attribute an object is stored in): locals
  ``module:func.name``, globals ``module:name``, attributes of a package
  class ``module:Class.attr`` where ``Class`` is the most basic class of
  the package (along the inheritance) that assigns the attribute, so that a
  publisher created in a base class in one module and used by a subclass in
  another is one handle; an object created and used without being stored
  ``new@<file>:<line>:<col>``;
* loops: ``<file>@<line>:<col>``.

Objects are typed by a small flow-insensitive evaluation: what a name or an
attribute is assigned anywhere in its scope (``self.x = ...`` in any method
of the class or its package bases), what a package function returns, the
classes of the package (``Talker()`` is an instance of ``Talker``;
``self`` in a method of a subclass of ``rclpy.node.Node`` is a node, so
``self.create_publisher(...)`` is a ROS call). A call through ``self`` of a
method the class does not define (a hook a subclass provides) goes to a
stub function ``module:Class.method``, and every method of a class gets a
call edge from the same method of each of its package base classes
(``Base.m`` may run ``Sub.m``); constructors and other dunder methods
excepted.

Left out: calls through objects passed as untyped parameters (except the
duck-typed methods of ``python_api.DUCK_METHODS`` and the handle aliases
made by calls with a handle as argument), objects stored in containers
(one handle per container), decorators that replace functions, ``exec``
and other dynamic code, ``getattr`` with computed names.
"""

from colcon_rsia.frontend.python.scopes import MODULE_FUNCTION
from colcon_rsia.frontend.python.scopes import read_module
from colcon_rsia.frontend.python.scopes import SourceError
from colcon_rsia.frontend.python.walk import extract_python_facts
from colcon_rsia.frontend.python.walk import normalize_msg_type

__all__ = [
    'MODULE_FUNCTION', 'SourceError', 'extract_python_facts',
    'normalize_msg_type', 'read_module']

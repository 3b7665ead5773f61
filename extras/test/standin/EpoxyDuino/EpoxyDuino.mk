# STAND-IN for EpoxyDuino's EpoxyDuino.mk (https://github.com/bxparks/EpoxyDuino),
# used only when the real EpoxyDuino is absent. Same interface for a test
# sketch's Makefile:
#
#   APP_NAME := FooTest
#   ARDUINO_LIBS := AUnit TinyParticle
#   include $(EPOXY_DUINO_DIR)/EpoxyDuino.mk
#
# `make` builds FooTest.out from FooTest.ino (plus *.cpp beside it and under
# each library's src/), `make run` runs it, `make clean` removes it.
# A library named in ARDUINO_LIBS is looked up in ARDUINO_LIB_DIRS, then
# beside this folder (extras/test/standin/, where the AUnit stand-in is); the name
# TinyParticle always finds the repository this file belongs to, whatever
# its folder is called.
#
# Unlike the real one it builds with the project's strict host flags:
# -Wall -Wextra -Werror and AddressSanitizer + UndefinedBehaviorSanitizer
# (any report aborts the program, so the test fails).

EPOXY_DUINO_DIR := $(abspath $(dir $(lastword $(MAKEFILE_LIST))))
EPOXY_STANDIN_REPO := $(abspath $(EPOXY_DUINO_DIR)/../../../..)
EPOXY_STANDIN_CORE := $(EPOXY_DUINO_DIR)/core

ARDUINO_LIB_DIRS ?=
CXX ?= g++
CXXFLAGS ?= -std=gnu++11 -g -O1 -Wall -Wextra -Werror \
  -fno-exceptions -fno-rtti -fno-threadsafe-statics \
  -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
CXXFLAGS += $(EXTRA_CXXFLAGS)
CPPFLAGS += $(EXTRA_CPPFLAGS)
CPPFLAGS += -DARDUINO=100 -DUNIX_HOST_DUINO -DEPOXY_DUINO -DEPOXY_CORE_AVR
CPPFLAGS += -I$(EPOXY_STANDIN_CORE)
LDFLAGS ?=

# First existing folder for each library.
epoxy_standin_find = $(firstword $(wildcard \
  $(if $(filter TinyParticle,$(1)),$(EPOXY_STANDIN_REPO)) \
  $(foreach d,$(ARDUINO_LIB_DIRS),$(d)/$(1)) \
  $(abspath $(EPOXY_DUINO_DIR)/../$(1))))
EPOXY_STANDIN_MODULES := $(foreach lib,$(ARDUINO_LIBS),$(call epoxy_standin_find,$(lib)))
ifneq ($(words $(EPOXY_STANDIN_MODULES)),$(words $(ARDUINO_LIBS)))
$(error EpoxyDuino stand-in: some of $(ARDUINO_LIBS) not found (found: $(EPOXY_STANDIN_MODULES)))
endif
CPPFLAGS += $(foreach m,$(EPOXY_STANDIN_MODULES),-I$(m) -I$(m)/src)

EPOXY_STANDIN_SRCS := $(wildcard $(EPOXY_STANDIN_CORE)/*.cpp) \
  $(foreach m,$(EPOXY_STANDIN_MODULES),$(if $(wildcard $(m)/src),\
    $(wildcard $(m)/src/*.cpp $(m)/src/*/*.cpp $(m)/src/*/*/*.cpp $(m)/src/*/*/*/*.cpp),\
    $(wildcard $(m)/*.cpp $(m)/utility/*.cpp))) \
  $(wildcard *.cpp)
EPOXY_STANDIN_HEADERS := $(wildcard $(EPOXY_STANDIN_CORE)/*.h $(EPOXY_STANDIN_CORE)/*/*.h) \
  $(foreach m,$(EPOXY_STANDIN_MODULES),$(wildcard $(m)/*.h $(m)/src/*.h $(m)/src/*/*.h* \
    $(m)/src/*/*/*.h* $(m)/src/*/*/*/*.h*))

.PHONY: all run clean
all: $(APP_NAME).out

# One compiler run: nothing is written outside this folder, so several tests
# can build at once.
$(APP_NAME).out: $(APP_NAME).ino $(EPOXY_STANDIN_SRCS) $(EPOXY_STANDIN_HEADERS) $(DEPS)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -x c++ $(APP_NAME).ino -x none $(EPOXY_STANDIN_SRCS) $(LDFLAGS) -o $@

run: $(APP_NAME).out
	./$(APP_NAME).out

clean: $(MORE_CLEAN)
	rm -f $(APP_NAME).out $(GENERATED)

// The Interpreter's value stack, and the transforms a block collects.
// Part of the Interpreter (language/interpreter_state.hpp).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "language/checked_integer.hpp"
#include "language/interpreter.hpp"
#include "language/interpreter_state.hpp"
#include "runtime/objects/parameter_check.hpp"

namespace hexant::language {

// ------------------------------------------------------------------ stacks

Value Interpreter::pop() {
    if (stack_.empty()) throw std::logic_error("hexant: value stack underflow");
    Value v = std::move(stack_.back());
    stack_.pop_back();
    return v;
}

Value& Interpreter::top() {
    if (stack_.empty()) throw std::logic_error("hexant: value stack underflow");
    return stack_.back();
}

std::vector<Value> Interpreter::close_frame() {
    if (frames_.empty()) throw std::logic_error("hexant: frame stack underflow");
    const std::size_t begin = frames_.back();
    frames_.pop_back();
    std::vector<Value> values(
        std::make_move_iterator(stack_.begin() + static_cast<std::ptrdiff_t>(begin)),
        std::make_move_iterator(stack_.end()));
    stack_.resize(begin);
    return values;
}

std::string Interpreter::pop_name() {
    if (names_.empty()) throw std::logic_error("hexant: name stack underflow");
    std::string n = std::move(names_.back());
    names_.pop_back();
    return n;
}

void Interpreter::apply_transform(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty()) fail(where, "a transformation does not belong here");
    Block& b = blocks.back();
    if (auto* object = std::get_if<runtime::ObjectRecord>(&b)) {
        // As in POV-Ray, an object's texture moves with it.
        if (object->texture) object->texture->transform_by(step);
        object->transform.append(std::move(step));
    } else if (auto* light = std::get_if<runtime::LightRecord>(&b)) {
        light->transform.append(std::move(step));
    } else if (auto* camera = std::get_if<runtime::CameraRecord>(&b)) {
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Transform;
        item.step = std::move(step);
        camera->items.push_back(std::move(item));
    } else if (auto* texture = std::get_if<runtime::Texture>(&b)) {
        texture->transform_by(step);
    } else if (auto* pigment = std::get_if<runtime::Pigment>(&b)) {
        // (A declared uv-mapped pigment takes no transform from outside
        // its own block, as in POV-Ray: runtime/texture/material.hpp, UvMapping.)
        if (pigment->uv_mapping != runtime::UvMapping::Closed)
            pigment->transform.append(std::move(step));
    } else if (auto* normal = std::get_if<runtime::Normal>(&b)) {
        if (normal->uv_mapping != runtime::UvMapping::Closed)
            normal->transform.append(std::move(step));
    } else if (auto* fog = std::get_if<runtime::Fog>(&b)) {
        // (POV-Ray turns a fog's up vector; a translation does not move it.)
        if (step.kind == runtime::TransformKind::Translate) return;
        fog->up_transform.append(std::move(step));
    } else if (auto* sky = std::get_if<runtime::SkySphere>(&b)) {
        sky->transform.append(std::move(step));
    } else if (auto* transform = std::get_if<runtime::Transform>(&b)) {
        transform->append(std::move(step));
    } else if (auto* material = std::get_if<MaterialBuilder>(&b)) {
        if (material->texture) material->texture->transform_by(step);
    } else {
        fail(where, "a transformation does not belong here");
    }
}

void Interpreter::apply_deformation(runtime::TransformStep step, const p::position& where) {
    if (blocks.empty() || !std::holds_alternative<runtime::ObjectRecord>(blocks.back()))
        fail(where, "a deformation belongs in an object");
    apply_transform(std::move(step), where);
}

}  // namespace hexant::language
